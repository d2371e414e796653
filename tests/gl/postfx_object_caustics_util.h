#pragma once
// Shared set-up and measurements of the object-caustics GL tests.
#include <cmath>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include <postfx/postfx.h>

#include <object_caustics_metrics.h>
#include <object_caustics_reference.h>
#include <object_caustics_scene.h>

#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace postfxtest {

// The scene fixtures, the CPU reference and the map measurements live in ocean_reference (the
// report measures the same scene).
using ocean::reference::CausticReference;
using ocean::reference::focusTexel;
using ocean::reference::gaussianBlur;
using ocean::reference::GlMesh;
using ocean::reference::makeCubeMesh;
using ocean::reference::makeRingMesh;
using ocean::reference::makeSphereMesh;
using ocean::reference::mapFlux;
using ocean::reference::readObjectMap;
using ocean::reference::ReceiverMap;
using ocean::reference::RingCaster;
using ocean::reference::SphereCaster;
using ocean::reference::texelOnPlane;
using ocean::reference::traceRingReference;
using ocean::reference::traceSphereReference;

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

bool allFinite(const std::vector<glm::dvec3>& values);

}  // namespace postfxtest
