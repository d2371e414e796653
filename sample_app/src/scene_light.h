#pragma once
// A point or spot light of the sample's scene (a diver's torch, a lamp): what the renderer lights
// the G-buffer with directly (with a shadow map from the light) and what the plugin is given
// for its object caustics. Set by a preset or by --light (light_spec.h).
#include <glm/glm.hpp>

namespace ocean {

// The most lights the sample renders (each has two depth maps: shadow and receivers).
inline constexpr int kMaxSceneLights = 4;

struct SceneLight {
  enum class Type { Point, Spot } type = Type::Spot;
  glm::dvec3 position{0.0};              // metres, y up, water at y = 0
  glm::dvec3 direction{0.0, -1.0, 0.0};  // spot: the axis it shines along (unit)
  // Radiant intensity, linear RGB: the irradiance (the sample's HDR units, the sun's are ~3) it
  // gives at 1 m on its axis on a surface facing it, through clear water.
  glm::vec3 intensity{40.0f};
  double range = 20.0;             // m: casters farther than this make no caustics from it
  float coneAngleDegrees = 40.0f;  // spot: full apex angle, (0, 180)
  float coneSoftness = 0.3f;       // spot: share of the half-angle faded at the edge, [0, 1]
};

}  // namespace ocean
