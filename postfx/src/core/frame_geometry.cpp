#include "core/frame_geometry.h"

#include <cmath>

namespace postfx::detail {

double tileFraction(double metres, double period) {
  const double f = metres / period - std::floor(metres / period);
  return f >= 1.0 ? 0.0 : f;  // floor rounding can land exactly on 1
}

glm::dvec3 refractedSunDown(const glm::dvec3& towardSun, double ior) {
  return glm::refract(-towardSun, glm::dvec3(0.0, 1.0, 0.0), 1.0 / ior);
}

glm::dvec3 incidencePlaneNormal(const glm::dvec3& towardSun) {
  const glm::dvec3 h(-towardSun.z, 0.0, towardSun.x);
  const double len = glm::length(h);
  return len > 1e-9 ? h / len : glm::dvec3(1.0, 0.0, 0.0);
}

glm::dmat3 viewToWorldRotation(const glm::mat4& view) {
  return glm::transpose(glm::dmat3(glm::mat3(view)));
}

}  // namespace postfx::detail
