#pragma once
// Shared set-up and measurements of the object-caustics GL tests.
#include <cmath>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include <postfx/postfx.h>

#include "postfx_object_caustics_fixtures.h"
#include "postfx_object_caustics_reference.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace postfxtest {

// Unit vector toward a sun at the given zenith and azimuth angles (degrees; azimuth from +x
// toward +z).
inline constexpr double kPi = 3.14159265358979323846;

inline glm::dvec3 sunAt(double zenithDegrees, double azimuthDegrees) {
  const double z = zenithDegrees * kPi / 180.0, a = azimuthDegrees * kPi / 180.0;
  return {std::sin(z) * std::cos(a), std::cos(z), std::sin(z) * std::sin(a)};
}

inline glm::dmat4 translation(const glm::dvec3& t) {
  glm::dmat4 m(1.0);
  m[3] = glm::dvec4(t, 1.0);
  return m;
}

// A host frame: a small G-buffer looking at the receiver plane y = 0 (with the sphere `caster`
// in it when given), water far below (the casters are in air), the sun and receiver map given.
struct ObjectHost {
  explicit ObjectHost(const glm::dvec3& towardSun, double receiverHalf = 4.0,
                      const SceneSpec& spec = defaultSpec());
  ~ObjectHost();
  static SceneSpec defaultSpec();

  postfx::FrameDesc frame(const postfx::CasterMesh* casters, int count,
                          const postfx::ObjectCausticsSettings& settings) const;

  glm::dvec3 towardSun;
  Scene scene;
  ReceiverMap receivers;
  GLuint water = 0;
};

inline ContextPtr makeObjectContext(postfx::Feature extra = postfx::Feature::None) {
  return makeContext(postfx::Feature::ObjectCaustics | extra);
}

int objectPassIndex(const postfx::FrameStats& stats);

// The plugin's map read back as doubles (rgb), size x size.
std::vector<glm::dvec3> readObjectMap(const postfx::ObjectCausticMap& map);

// Total flux (sun irradiance 1, m^2) in a map of relative irradiance.
glm::dvec3 mapFlux(const std::vector<glm::dvec3>& map, const postfx::ObjectCausticMap& placement);

// Brightest spot: centroid (texel units, continuous) of the texels >= half the maximum of the
// green channel within +-radius texels of the maximum.
glm::dvec2 focusTexel(const std::vector<glm::dvec3>& map, int size, int radius = 6);

// Where the map texel position lies on the plane y = planeY (projected along the light).
glm::dvec3 texelOnPlane(const postfx::ObjectCausticMap& map, const glm::dvec2& texel,
                        double planeY);

bool allFinite(const std::vector<glm::dvec3>& values);

}  // namespace postfxtest
