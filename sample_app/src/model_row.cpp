#include "model_row.h"

#include <algorithm>
#include <cmath>

namespace ocean {

glm::dvec3 rowPosition(const Camera& camera, std::size_t index, std::size_t count, double height,
                       double (*sandHeight)(double x, double z)) {
  const glm::dvec3 forward = camera.forward();
  const glm::dvec3 from = camera.position;
  double ahead = 6.0;
  for (double t = 0.05; t < 40.0; t += 0.05) {
    const glm::dvec3 p = from + t * forward;
    if (p.y <= sandHeight(p.x, p.z)) {
      ahead = std::clamp(0.7 * t, 2.5, 12.0);
      break;
    }
  }
  const glm::dvec3 centre = from + ahead * forward;
  glm::dvec3 right = glm::cross(forward, glm::dvec3(0.0, 1.0, 0.0));
  right = glm::length(right) > 1e-6 ? glm::normalize(right) : glm::dvec3(1.0, 0.0, 0.0);
  // The row spans at most 80% of a 16:9 view's width at that distance, 3 m apart at most.
  const double viewWidth = 2.0 * ahead * std::tan(0.5 * camera.fovY) * 16.0 / 9.0;
  const double spacing = std::min(3.0, 0.8 * viewWidth / double(std::max<std::size_t>(count, 1)));
  const double offset = spacing * (double(index) - 0.5 * double(count - 1));
  const glm::dvec3 at = centre + offset * right;
  // Centred on the ray, its top 10 cm under the water at most; resting on the sand at least.
  const double bottom = std::min(at.y - 0.5 * height, -0.1 - height);
  const double above = std::max(0.0, bottom - sandHeight(at.x, at.z));
  return {at.x, above, at.z};
}

}  // namespace ocean
