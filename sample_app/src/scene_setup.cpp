#include "scene_setup.h"

#include "caster_admission.h"
#include "model_row.h"
#include "model_spec.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>

#include <scene/default_scene.h>
#include <scene/gltf_loader.h>
#include <scene/harbour_scene.h>
#include <scene/pool_scene.h>
#include <scene/seabed.h>
#include <scene/wake_ball.h>

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

// The scene-space bounding box of the model's instances.
void modelBounds(const ocean_scene::Model& model, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(std::numeric_limits<double>::infinity());
  hi = -lo;
  for (const ocean_scene::Instance& instance : model.instances) {
    const glm::dmat4 m(instance.transform);
    for (const glm::vec3& p : model.meshes[instance.mesh].positions) {
      const glm::dvec3 q(m * glm::dvec4(glm::dvec3(p), 1.0));
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
  }
}

}  // namespace

bool buildScene(const std::vector<ModelSpec>& userModels, ocean_scene::Model& scene,
                std::string& error, const ocean_scene::GltfLimits& limits, SceneKind kind,
                const Camera& camera) {
  if (kind == SceneKind::Pool) {
    if (!userModels.empty()) {
      error =
          "--model: the pool preset's scene takes no models (they are placed on the sea's sand)";
      return false;
    }
    scene = ocean_scene::buildPoolScene();
    return true;
  }
  ocean_scene::DefaultSceneParams params;
  std::vector<std::string> warnings;
  if (!ocean_scene::buildDefaultSceneWithModels(params, assetDirectory(), scene, error)) {
    return false;
  }
  for (size_t i = 0; i < userModels.size(); ++i) {
    const ModelSpec& spec = userModels[i];
    ocean_scene::Model model;
    std::string notes;
    ocean_scene::GltfLimits held = limits;
    held.raiseOption = "--model-limits";
    if (!ocean_scene::loadGlb(spec.path, model, error, &notes, held)) return false;
    if (!notes.empty()) warnings.push_back(spec.path + ": " + notes);
    glm::dvec3 lo, hi;
    modelBounds(model, lo, hi);
    // Without a position, user models stand in a row across the preset camera's view.
    ModelSpec placed = spec;
    if (!placed.position) {
      const double largest = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
      const double height =
          spec.fitMetres && largest > 0.0 ? (hi.y - lo.y) * *spec.fitMetres / largest : hi.y - lo.y;
      placed.position =
          rowPosition(camera, i, userModels.size(), std::isfinite(height) ? height : 0.0,
                      &ocean_scene::seabedHeight);
    }
    glm::dmat4 place;
    const glm::dvec2 unused(0.0);
    if (!placementTransform(placed, lo, hi, unused, &ocean_scene::seabedHeight, place, error)) {
      error = spec.path + ": " + error;
      return false;
    }
    // Instance names carry the file, so a warning about one names both file and node.
    for (ocean_scene::Instance& instance : model.instances) {
      instance.name = spec.path + (instance.name.empty() ? "" : " node '" + instance.name + "'");
    }
    ocean_scene::appendModel(scene, model, glm::mat4(place));
  }
  // The wake's ball: 0.5 m (wake_water.h, WakeDesc::ballRadius); moved every frame.
  if (kind == SceneKind::Wake) ocean_scene::addWakeBall(scene, 0.5);
  // The harbour's quay, pier and boat: in the model the renderer draws and the reference
  // traces (sceneTriangles), like every other part of the scene.
  if (kind == SceneKind::Harbour) ocean_scene::appendModel(scene, ocean_scene::buildHarbourScene());
  admitCasters(scene, warnings);
  for (const std::string& warning : warnings) {
    std::fprintf(stderr, "ocean_sample: warning: %s\n", warning.c_str());
  }
  return true;
}

}  // namespace ocean
