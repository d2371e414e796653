#pragma once
// Builds the CPU scene the sample renders: the procedural default scene, the generated glTF
// assets, and any --model files the user adds.
#include <string>
#include <vector>

#include <scene/gltf_limits.h>
#include <scene/model.h>

#include "camera.h"
#include "model_spec.h"
#include "scene_kind.h"

namespace ocean {

// userModels are the --model and --model-file files with their placement (model_spec.h), each
// held to `limits` (a refusal names --model-limits, which raises them). Loader notes and
// casters left out of the object caustics are printed to stderr as warnings; the first error
// returns false with a one-line message. SceneKind::Pool builds the pool (scene/pool_scene.h)
// with its default dimensions, and takes no user models (their placement rests them on the
// sand); SceneKind::Harbour adds the harbour (scene/harbour_scene.h) to the sea's scene.
// Models without a position stand in a row across `camera`'s view (model_row.h): the preset's
// camera, so that every preset shows them.
bool buildScene(const std::vector<ModelSpec>& userModels, ocean_scene::Model& scene,
                std::string& error, const ocean_scene::GltfLimits& limits = {},
                SceneKind kind = SceneKind::Sea, const Camera& camera = Camera{});

}  // namespace ocean
