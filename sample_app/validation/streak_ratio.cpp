#include "streak_ratio.h"

#include <cmath>

namespace ocean::validation {

double streakRatio(const std::vector<double>& values, int countX, int countZ, double binX,
                   double binZ, const glm::dvec3& towardSun) {
  glm::dvec2 along(towardSun.x, towardSun.z);
  const double length = glm::length(along);
  along = length > 1e-12 ? along / length : glm::dvec2(1.0, 0.0);
  double acrossEnergy = 0.0, alongEnergy = 0.0;
  auto at = [&](int i, int j) { return values[size_t(j) * size_t(countX) + size_t(i)]; };
  for (int j = 1; j + 1 < countZ; ++j) {
    for (int i = 1; i + 1 < countX; ++i) {
      const glm::dvec2 gradient((at(i + 1, j) - at(i - 1, j)) / (2.0 * binX),
                                (at(i, j + 1) - at(i, j - 1)) / (2.0 * binZ));
      const double a = glm::dot(gradient, along);
      const double c = gradient.x * -along.y + gradient.y * along.x;
      alongEnergy += a * a;
      acrossEnergy += c * c;
    }
  }
  return alongEnergy > 0.0 ? acrossEnergy / alongEnergy : 0.0;
}

}  // namespace ocean::validation
