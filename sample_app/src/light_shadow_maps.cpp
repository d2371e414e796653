#include "light_shadow_maps.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace ocean {

glm::dmat4 lightWorldToClip(const SceneLight& light, double& fovY) {
  const bool spot = light.type == SceneLight::Type::Spot;
  const glm::dvec3 axis = spot ? glm::normalize(light.direction) : glm::dvec3(0.0, -1.0, 0.0);
  fovY = glm::radians(spot ? std::min(double(light.coneAngleDegrees) + 6.0, 170.0)
                           : kPointLightShadowFovDegrees);
  const glm::dvec3 up = std::abs(axis.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dmat4 view = glm::lookAt(light.position, light.position + axis, up);
  // Forward [0,1] depth (the sample sets ZERO_TO_ONE clip control for every pass); 0.1 m to
  // 200 m holds a torch's scene at under a millimetre of depth resolution at 10 m in D32F.
  return glm::perspectiveRH_ZO(fovY, 1.0, 0.1, 200.0) * view;
}

}  // namespace ocean
