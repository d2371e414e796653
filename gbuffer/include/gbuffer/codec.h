#pragma once
// C++ side of the G-buffer contract. The functions are the very ones the shaders run
// (shaders/shared/gbuffer_codec.h), in namespace gbuffer::shared.
#include <glm/glm.hpp>

#include "shared/common.h"  // before the namespace: it includes GLM

namespace gbuffer {
#include "shared/gbuffer_codec.h"

enum class DepthConvention : int {
  ReverseZ = shared::DEPTH_REVERSE_Z,                // recommended: glClipControl(LOWER_LEFT,
                                                     // ZERO_TO_ONE), clear 0, GL_GREATER
  ForwardZeroToOne = shared::DEPTH_FORWARD_ZERO_ONE, // ZERO_TO_ONE clip, clear 1, GL_LESS
  ForwardNegOneToOne = shared::DEPTH_FORWARD_NEG_ONE // GL default clip, clear 1, GL_LESS
};

enum class NormalEncoding : int {
  Octahedral = shared::NORMAL_OCTAHEDRAL,  // world-space, RG16_SNORM (or RG16F/RG32F)
  WorldXyz = shared::NORMAL_XYZ,           // world-space vector, RGB(A)16F/32F
  WorldXyzUnorm = shared::NORMAL_XYZ_UNORM // world-space n*0.5+0.5, RGB(A)8 / RGB10_A2
};

// Projection parameters the reconstruction takes, from a column-major perspective matrix.
struct ProjectionParams {
  glm::vec4 xy;  // (P[0][0], P[1][1], P[2][0], P[2][1])
  glm::vec2 z;   // (P[2][2], P[3][2])
};

inline ProjectionParams projectionParams(const glm::mat4& projection) {
  return {{projection[0][0], projection[1][1], projection[2][0], projection[2][1]},
          {projection[2][2], projection[3][2]}};
}

}  // namespace gbuffer
