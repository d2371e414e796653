#include "sun_light.h"

#include <algorithm>

#include "shared/sample_optics.h"

namespace ocean {

glm::vec3 sunIrradianceAboveWater(const Sun& sun) {
  const glm::dvec3 toSun = sun.direction();
  if (!(toSun.y > 0.0)) return glm::vec3(0.0f);
  // A low sun crosses more air: dimmer and redder (a fixed extinction per air mass).
  const float airMass = float(1.0 / std::max(toSun.y, 0.02));
  return sun.irradiance * glm::exp(-glm::vec3(0.02f, 0.035f, 0.07f) * (airMass - 1.0f));
}

float sunTransmission(const Sun& sun, double ior) {
  const double elevation = sun.direction().y;
  if (!(elevation > 0.0)) return 0.0f;
  return 1.0f - shared::fresnelReflectance(float(elevation), 1.0f, float(ior));
}

glm::vec3 sunIrradianceBelowSurface(const Sun& sun, double ior) {
  return sunIrradianceAboveWater(sun) * sunTransmission(sun, ior);
}

}  // namespace ocean
