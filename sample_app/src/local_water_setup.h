#pragma once
// Gives the renderer the local water a preset's scene has (the pool's ripples), before the
// plugin is created, so that PluginSetup asks for Feature::LocalWater only where there is some.
#include <string>

#include <scene/model.h>

#include "camera.h"
#include "renderer.h"

namespace ocean {

// Nothing for the sea's presets; the pool's simulation for SceneKind::Pool, the towed ball's
// wake for SceneKind::Wake (`scene` is the one buildScene made for it). The GL context must be
// current. False with a message on failure.
bool attachLocalWater(const Preset& preset, const ocean_scene::Model& scene, Renderer& renderer,
                      std::string& error);

}  // namespace ocean
