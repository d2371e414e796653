#include "scene_setup.h"

#include <glm/gtc/matrix_transform.hpp>

#include <filesystem>

#include <scene/default_scene.h>
#include <scene/seabed.h>

namespace ocean {
namespace {

// The generated assets live next to the executable (installed or in the build tree).
std::string assetDirectory() {
  std::error_code code;
  const auto self = std::filesystem::read_symlink("/proc/self/exe", code);
  if (!code) {
    const auto besideExecutable = self.parent_path() / "assets";
    if (std::filesystem::is_directory(besideExecutable, code)) return besideExecutable.string();
  }
  return OCEAN_ASSET_DIR;
}

}  // namespace

bool buildScene(const std::vector<std::string>& userModels, ocean_scene::Model& scene,
                std::string& error) {
  ocean_scene::DefaultSceneParams params;
  if (!ocean_scene::buildDefaultSceneWithModels(params, assetDirectory(), scene, error)) {
    return false;
  }
  // User models stand on the sand in a row in front of the seabed preset's camera.
  std::vector<ocean_scene::ModelPlacement> placements;
  for (size_t i = 0; i < userModels.size(); ++i) {
    const double x = 3.0 * double(i) - 1.5 * double(userModels.size() - 1);
    const double z = 5.0;
    const double y = ocean_scene::seabedHeight(x, z) + 1.0;
    placements.push_back({"user" + std::to_string(i), userModels[i],
                          glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z))});
  }
  // Absolute or relative to the working directory: addModels joins with "" harmlessly.
  return placements.empty() || ocean_scene::addModels(scene, "", placements, error);
}

}  // namespace ocean
