#pragma once
// C++ side of the G-buffer contract. The functions are the very ones the shaders run
// (shaders/shared/gbuffer_codec.h), in namespace gbuffer::shared.
#include <glm/glm.hpp>

#include "shared/common.h"  // before the namespace: it includes GLM

namespace gbuffer {
#include "shared/gbuffer_codec.h"

enum class DepthConvention : int {
  ReverseZ = shared::DEPTH_REVERSE_Z,                 // recommended: glClipControl(LOWER_LEFT,
                                                      // ZERO_TO_ONE), clear 0, GL_GREATER
  ForwardZeroToOne = shared::DEPTH_FORWARD_ZERO_ONE,  // ZERO_TO_ONE clip, clear 1, GL_LESS
  ForwardNegOneToOne = shared::DEPTH_FORWARD_NEG_ONE  // GL default clip, clear 1, GL_LESS
};

enum class NormalEncoding : int {
  Octahedral = shared::NORMAL_OCTAHEDRAL,   // world-space, RG16_SNORM (or RG16F/RG32F)
  WorldXyz = shared::NORMAL_XYZ,            // world-space vector, RGB(A)16F/32F
  WorldXyzUnorm = shared::NORMAL_XYZ_UNORM  // world-space n*0.5+0.5, RGB(A)8 / RGB10_A2
};

// Projection parameters the reconstruction takes (see shared::viewPositionFromDepth). Give the
// projection in double where you have it: the forward conventions need P22 + 1 in double.
struct ProjectionParams {
  glm::vec4 xy;  // (P[0][0], P[1][1], P[2][0], P[2][1])
  glm::vec2 z;   // (P[2][2] + k, P[3][2]), k = 0 reverse-Z, 1 forward
};

inline ProjectionParams projectionParams(const glm::dmat4& projection, DepthConvention convention) {
  const double k = convention == DepthConvention::ReverseZ ? 0.0 : 1.0;
  return {glm::vec4(projection[0][0], projection[1][1], projection[2][0], projection[2][1]),
          glm::vec2(projection[2][2] + k, projection[3][2])};
}

}  // namespace gbuffer
