#pragma once
// Builds the CPU scene the sample renders: the procedural default scene, the generated glTF
// assets, and any --model files the user adds.
#include <string>
#include <vector>

#include <scene/model.h>

namespace ocean {

bool buildScene(const std::vector<std::string>& userModels, ocean_scene::Model& scene,
                std::string& error);

}  // namespace ocean
