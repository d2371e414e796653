#include "water_pick.h"

#include <cmath>

namespace ocean {

bool pickWaterPlane(const Camera& camera, double aspect, glm::dvec2 ndc, double level,
                    glm::dvec2& worldXZ) {
  const double tanHalf = std::tan(0.5 * camera.fovY);
  // Camera space looks along -z (Camera::rotation's columns are right, up, back).
  const glm::dvec3 local(ndc.x * tanHalf * aspect, ndc.y * tanHalf, -1.0);
  const glm::dvec3 direction = glm::normalize(camera.rotation() * local);
  const double height = level - camera.position.y;
  // Parallel (or nearly: a hit beyond 1e5 m) and away from the plane both miss.
  if (!(std::abs(direction.y) > 1e-12)) return false;
  const double t = height / direction.y;
  if (!(t > 0.0) || t > 1e5) return false;
  const glm::dvec3 hit = camera.position + direction * t;
  worldXZ = glm::dvec2(hit.x, hit.z);
  return true;
}

}  // namespace ocean
