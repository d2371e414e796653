#include "caustic_light_units.h"

#include <algorithm>

#include "core/shared_math.h"  // the plugin's own attenuation functions (shaders/postfx)
#include "seabed_reference.h"

namespace ocean::reference {

CausticLightUnits causticLightUnits(const postfx::FrameDesc& frame) {
  CausticLightUnits units;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const glm::dvec3 up = -refractSunRay(sun, 0.0, 0.0, frame.water.ior);
  // The same floor as the plugin's frame constants (seabed_caustics/caustics_constants.cpp).
  units.upY = std::max(up.y, 1e-6);
  units.lightScale = frame.sun.irradiance * frame.caustics.intensity;
  units.absorptionPerDepth = glm::vec3(glm::dvec3(frame.water.absorption) / units.upY);
  units.objectLightScale = frame.sun.irradiance * frame.objectCaustics.settings.intensity;
  units.objectIntensity = frame.objectCaustics.settings.intensity;
  units.fadeDepth = frame.caustics.surfaceFadeDepth;
  if (frame.viewExtinction == postfx::ViewExtinction::Plugin)
    units.viewExtinction = frame.water.absorption + frame.water.scattering;
  units.levelRelative = static_cast<float>(frame.water.level - frame.camera.position.y);
  units.mirrorY = std::max(sun.y, 0.0);
  if (sun.y > 0.0) {
    units.reflectedLightScale =
        frame.sun.irradiance * frame.reflectedCaustics.intensity *
        static_cast<float>(fresnelReflectance(sun.y, double(frame.water.ior)));
  }
  units.includeMirrorMean = frame.reflectedCaustics.includeMirrorMean;
  return units;
}

namespace {

// The plugin's ViewExtinction::Plugin factor: the submerged part of the view ray, attenuated.
glm::vec3 viewTransmittance(const CausticLightUnits& units, float depth, double viewDistance) {
  return glm::exp(-units.viewExtinction *
                  postfx::shared::submergedViewLength(static_cast<float>(viewDistance), depth,
                                                      units.levelRelative));
}

}  // namespace

glm::vec3 referenceCausticLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                double depthBelow, double tracedIrradiance, double viewDistance) {
  const float depth = static_cast<float>(depthBelow);
  const float bracket = static_cast<float>(tracedIrradiance * units.upY);
  return postfx::shared::sanitizeAlbedo(albedo) * units.lightScale *
         postfx::shared::causticTransmittance(units.absorptionPerDepth, depth) *
         (bracket * postfx::shared::causticSurfaceFade(depth, units.fadeDepth)) *
         viewTransmittance(units, depth, viewDistance);
}

glm::vec3 referenceObjectCausticLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                      double depthBelow, const glm::dvec3& tracedIrradiance,
                                      double viewDistance) {
  const float depth = static_cast<float>(depthBelow);
  const glm::vec3 bracket(tracedIrradiance * units.upY);
  return postfx::shared::sanitizeAlbedo(albedo) * units.objectLightScale *
         postfx::shared::causticTransmittance(units.absorptionPerDepth, depth) * bracket *
         viewTransmittance(units, depth, viewDistance);
}

glm::vec3 referenceReflectedLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                  double depthBelow, double tracedReflected, double flatMirrorLight,
                                  double viewDistance) {
  const double relative =
      units.includeMirrorMean ? tracedReflected : tracedReflected - flatMirrorLight;
  const float bracket = static_cast<float>(relative * units.mirrorY);
  return postfx::shared::sanitizeAlbedo(albedo) * units.reflectedLightScale * bracket *
         viewTransmittance(units, static_cast<float>(depthBelow), viewDistance);
}

glm::vec3 referenceLocalCausticLight(const CausticLightUnits& units, const glm::vec3& albedo,
                                     double depthBelow, const glm::dvec3& tracedIrradiance,
                                     double viewDistance) {
  const float depth = static_cast<float>(depthBelow);
  return postfx::shared::sanitizeAlbedo(albedo) * units.objectIntensity *
         glm::vec3(tracedIrradiance) * viewTransmittance(units, depth, viewDistance);
}

}  // namespace ocean::reference
