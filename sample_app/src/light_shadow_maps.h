#pragma once
// Depth maps from each point or spot light of the scene: the shadow map the sample lights with
// (all geometry) and the receiver map the plugin's object caustics land on (the same view
// without the caustic casters), both perspective from the light, forward [0, 1] depth.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <vector>

#include "scene_light.h"
#include "shadow_map.h"

namespace ocean {

// A spot's frustum holds its cone (plus a margin for the shadow filter); a point light's looks
// straight down over a 120 degree cone (the sample has no cube maps: its light beyond that is
// unshadowed and makes no caustics).
inline constexpr double kPointLightShadowFovDegrees = 120.0;

// World -> light clip (double, translation included) of `light`'s depth maps, and the vertical
// field of view it uses (radians).
glm::dmat4 lightWorldToClip(const SceneLight& light, double& fovY);

struct LightDepthMaps {
  SceneLight light;
  glm::dmat4 worldToClip{1.0};
  double fovY = 0.0;
  ShadowMap shadow;     // all geometry
  ShadowMap receivers;  // without the caustic casters (created when asked for)
};

}  // namespace ocean
