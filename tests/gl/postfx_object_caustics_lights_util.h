#pragma once
// Set-up and measurements of the local lights' object-caustics GL tests: a receiver depth map
// seen from a light (perspective), the light's caustic map read back, and what lands on a plane.
#include <epoxy/gl.h>

#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include <object_caustics_scene.h>

#include <postfx/postfx.h>
#include <postfx/testing.h>

#include "postfx_object_caustics_util.h"

namespace postfxtest {

// The reference's receiver map of the plane y = planeY (within +-planeHalf in x and z; 0:
// unbounded) seen from a light at `position` looking along `axis`, over a square of half-angle
// halfDegrees, its depth range wide enough for any of these tests' planes (near 1 mm).
class LightReceiverMap : public ocean::reference::LightReceiverMap {
 public:
  LightReceiverMap(const glm::dvec3& position, const glm::dvec3& axis, double halfDegrees,
                   double planeY, int texels, double planeHalf = 0.0)
      : ocean::reference::LightReceiverMap(position, axis, 2.0 * halfDegrees, planeY, texels,
                                           1e4 + 10.0 * std::abs(position.y - planeY), 1e-3,
                                           planeHalf) {}
};

// A light's caustic map read back (testing::lightCausticMap), with what it takes to place its
// texels in the world.
struct LightMap {
  LightMap(const postfx::testing::LightCausticMap& map, const glm::dvec3& lightPosition);
  // Unit direction from the light through texel coordinates (x, y) (continuous, texel centres
  // at i + 0.5).
  glm::dvec3 direction(double x, double y) const;
  // Where that direction meets the plane y = planeY.
  glm::dvec3 onPlane(double x, double y, double planeY) const;
  // Flux (per unit intensity, the map's units x m^2) landing on the plane y = planeY:
  // sum of E * r^2 * the texel's solid angle.
  glm::dvec3 fluxOnPlane(double planeY) const;
  // Flux-weighted centroid and RMS distance from it (m) on the plane, green channel.
  void spotOnPlane(double planeY, glm::dvec3& centroid, double& rmsRadius) const;
  // Largest green value and its texel.
  double peak(int& x, int& y) const;
  bool allFinite() const;

  std::vector<glm::dvec3> value;
  int size = 0;
  glm::dmat4 clipInverse{1.0};
  glm::dvec3 light{0.0};
};

// A context with Feature::ObjectCaustics (and `extra`) for up to maxLocalLights lights.
ContextPtr makeLightContext(int maxLocalLights, postfx::Feature extra = postfx::Feature::None);

// Object-caustics settings with the given ray grid and map sizes (small: fast tests).
postfx::ObjectCausticsSettings sizedSettings(int gridSize, int mapSize);

// The host's frame with the lights given and the sun left out (sunCaustics false).
postfx::FrameDesc lightsOnlyFrame(const ObjectHost& host, const postfx::CasterMesh* casters,
                                  int casterCount, const postfx::LocalLight* lights, int lightCount,
                                  const postfx::ObjectCausticsSettings& settings);

// Whether every value of the host's target is finite.
bool finiteTarget(const ObjectHost& host);

// A point/spot light with its receivers.
postfx::LocalLight makeLight(postfx::LocalLightType type, const glm::dvec3& position,
                             const glm::dvec3& direction, const postfx::SunShadowMap& receivers);

}  // namespace postfxtest
