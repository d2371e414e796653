#pragma once
// The wake preset's object: a buoyant orange ball towed across the sea (its instance is moved
// every frame), added to the default scene.
#include "scene/model.h"

namespace ocean_scene {

inline constexpr const char* kWakeBallName = "wake_ball";

// Appends a unit icosphere instance named kWakeBallName, scaled to `radius` (m, > 0) at the
// origin, with a matte orange material (not a caustic caster).
void addWakeBall(Model& model, double radius);

}  // namespace ocean_scene
