#pragma once
// How the host's inputs are encoded: typed, so that a G-buffer convention cannot be passed as a
// bare number. The values equal gbuffer's (shaders/shared/gbuffer_codec.h; static_assert in
// the library), so a host that uses this repository's gbuffer module may cast between the two.
#include <cstdint>

namespace postfx {

using GlName = std::uint32_t;  // a GL object name (GLuint)
using GlEnum = std::uint32_t;  // a GL enum (GLenum)

// Window-space depth of a depth texture (camera G-buffer, sun shadow map, receiver map).
enum class DepthConvention : std::int32_t {
  ReverseZ = 0,          // glClipControl(LOWER_LEFT, ZERO_TO_ONE), near 1, far/sky 0 (recommended)
  ForwardZeroToOne = 1,  // glClipControl(LOWER_LEFT, ZERO_TO_ONE), near 0, far/sky 1
  ForwardNegOneToOne = 2,  // GL's default [-1,1] clip space: near 0, far/sky 1
};

// How the G-buffer stores the world-space normal, and the formats accepted for each.
enum class NormalEncoding : std::int32_t {
  // Octahedral xy in [-1,1]^2: GL_RG16_SNORM, GL_RG8_SNORM, GL_RG16F, GL_RG32F, GL_RGBA16_SNORM,
  // GL_RGBA16F, GL_RGBA32F (rg read).
  Octahedral = 0,
  // The vector itself: GL_RGB16F, GL_RGBA16F, GL_RGB32F, GL_RGBA32F, GL_RGB16_SNORM,
  // GL_RGBA16_SNORM, GL_RGBA8_SNORM, GL_R11F_G11F_B10F (unsigned: normals with y >= 0 only).
  WorldXyz = 1,
  // n * 0.5 + 0.5: GL_RGBA8, GL_RGB8, GL_RGB10_A2, GL_RGBA16, GL_RGB16.
  WorldXyzUnorm = 2,
};

// Index type of a caster's index buffer (CasterMesh::indexType); the values are the GL enums.
enum class IndexType : std::uint32_t {
  UnsignedByte = 0x1401,   // GL_UNSIGNED_BYTE
  UnsignedShort = 0x1403,  // GL_UNSIGNED_SHORT
  UnsignedInt = 0x1405,    // GL_UNSIGNED_INT
};

// Stable names for messages and logs, e.g. "ReverseZ"; "unknown" for a value outside the enum.
const char* toString(DepthConvention convention) noexcept;
const char* toString(NormalEncoding encoding) noexcept;
const char* toString(IndexType type) noexcept;

}  // namespace postfx
