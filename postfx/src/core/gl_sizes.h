#pragma once
// What GL holds for a texture or buffer, asked of GL: how the passes account for the memory
// they allocated, so that a test can hold the up-front estimate (memory_estimate.h) to it.
#include <epoxy/gl.h>

#include <cstdint>

namespace postfx::detail {

// Bytes of every level of an immutable texture (width x height x depth or layers, summed over
// GL_TEXTURE_IMMUTABLE_LEVELS) at `bytesPerTexel`; 0 for 0 or a texture without storage.
inline std::uint64_t textureBytes(GLuint texture, std::uint64_t bytesPerTexel) {
  if (texture == 0) return 0;
  GLint levels = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  std::uint64_t texels = 0;
  for (GLint level = 0; level < levels; ++level) {
    GLint w = 0, h = 0, d = 0;
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &h);
    glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_DEPTH, &d);
    texels += std::uint64_t(w) * std::uint64_t(h) * std::uint64_t(d);
  }
  return texels * bytesPerTexel;
}

// GL_BUFFER_SIZE of a buffer; 0 for 0.
inline std::uint64_t bufferBytes(GLuint buffer) {
  if (buffer == 0) return 0;
  GLint64 bytes = 0;
  glGetNamedBufferParameteri64v(buffer, GL_BUFFER_SIZE, &bytes);
  return bytes > 0 ? static_cast<std::uint64_t>(bytes) : 0;
}

}  // namespace postfx::detail
