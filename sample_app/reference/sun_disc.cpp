#include "sun_disc.h"

#include <cmath>
#include <numbers>

namespace ocean::reference {

SunDisc::SunDisc(const glm::dvec3& towardSun, double angularRadius)
    : sun_(towardSun), radius_(angularRadius) {
  const glm::dvec3 helper =
      std::abs(sun_.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  side_ = glm::normalize(glm::cross(sun_, helper));
  up_ = glm::cross(side_, sun_);
}

glm::dvec3 SunDisc::direction(double u1, double u2) const {
  if (!(radius_ > 0.0)) return sun_;
  // Uniform over the disc: radius sqrt(u1), angle 2 pi u2; the tangent plane is exact to
  // second order in the radius (2e-5 rad for the real sun).
  const double r = radius_ * std::sqrt(u1), a = 2.0 * std::numbers::pi * u2;
  return glm::normalize(sun_ + std::tan(r) * (std::cos(a) * side_ + std::sin(a) * up_));
}

}  // namespace ocean::reference
