#include "core/shadow_light.h"

#include <cmath>

namespace postfx::detail {

ShadowLight shadowLight(const glm::dmat4& m, DepthConvention convention) {
  auto row = [&m](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
  const glm::dvec4 x = row(0), y = row(1), z = row(2), w = row(3);
  ShadowLight light;
  const glm::dvec3 wXyz(w);
  if (glm::length(wXyz) > 1e-12 * std::abs(w.w)) {
    // Perspective: the eye is the point where clip x, y and w all vanish.
    const glm::dmat3 rows = glm::transpose(glm::dmat3(glm::dvec3(x), glm::dvec3(y), wXyz));
    if (std::abs(glm::determinant(rows)) > 0.0) {
      light.perspective = true;
      light.vector = glm::inverse(rows) * -glm::dvec3(x.w, y.w, w.w);
    }
    return light;
  }
  // Orthographic: clip x and y stay put along x.xyz cross y.xyz; orient it to growing depth,
  // which leads away from the light unless reverse-Z. (A map of constant depth has no growing
  // direction; its bias moves nothing, and either orientation will do.)
  glm::dvec3 axis = glm::cross(glm::dvec3(x), glm::dvec3(y));
  const double length = glm::length(axis);
  if (!(length > 0.0)) return light;
  axis /= length;
  if (glm::dot(axis, glm::dvec3(z)) < 0.0) axis = -axis;
  light.vector = convention == DepthConvention::ReverseZ ? axis : -axis;
  return light;
}

glm::dvec2 clipUnitsToMetres(const glm::dmat4& m) {
  const double row0 = glm::length(glm::dvec3(m[0][0], m[1][0], m[2][0]));
  const double row1 = glm::length(glm::dvec3(m[0][1], m[1][1], m[2][1]));
  return {row0 > 0.0 ? 2.0 / row0 : 0.0, row1 > 0.0 ? 2.0 / row1 : 0.0};
}

}  // namespace postfx::detail
