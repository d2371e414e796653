#pragma once
// Builds the CPU scene the sample renders: the procedural default scene, the generated glTF
// assets, and any --model files the user adds.
#include <string>
#include <vector>

#include <scene/model.h>

namespace ocean {

// userModels are --model arguments, FILE[@x,y,z][:fit=metres|none] (model_spec.h). Loader
// notes and casters left out of the object caustics are printed to stderr as warnings; the
// first error returns false with a one-line message.
bool buildScene(const std::vector<std::string>& userModels, ocean_scene::Model& scene,
                std::string& error);

}  // namespace ocean
