#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/default_scene.h"
#include "scene/gltf_loader.h"
#include "scene/scene_features.h"

namespace ocean_scene {

namespace {

constexpr float kDegrees = 3.14159265358979323846f / 180.0f;

glm::mat4 onSand(const glm::dvec2& xz, double heightAboveSand) {
  const double y = seabedHeight(xz.x, xz.y) + heightAboveSand;
  return glm::translate(glm::mat4(1.0f), glm::vec3(glm::dvec3(xz.x, y, xz.y)));
}

std::string joinPath(const std::string& dir, const std::string& file) {
  if (dir.empty()) return file;
  const char last = dir.back();
  return (last == '/' || last == '\\') ? dir + file : dir + "/" + file;
}

}  // namespace

std::vector<ModelPlacement> defaultModelPlacements() {
  using namespace features;
  std::vector<ModelPlacement> placements;
  placements.push_back(
      {"glass_sphere", "glass_sphere.glb", onSand(kGlassSphereXZ, kGlassSphereHeightAboveSand)});
  // The ring's tube radius is 0.05 m; 1 cm sunk so it does not float on the sloping sand.
  placements.push_back({"metal_ring", "metal_ring.glb",
                        onSand(kMetalRingXZ, 0.04) *
                            glm::rotate(glm::mat4(1.0f), 25.0f * kDegrees, {0.0f, 1.0f, 0.0f})});
  placements.push_back({"glass_bottle", "glass_bottle.glb", onSand(kGlassBottleXZ, -0.005)});
  // On its side with the axis horizontal, sunk to about a third of its girth.
  placements.push_back({"amphora", "amphora.glb",
                        onSand(kAmphoraXZ, 0.06) *
                            glm::rotate(glm::mat4(1.0f), 30.0f * kDegrees, {0.0f, 1.0f, 0.0f}) *
                            glm::rotate(glm::mat4(1.0f), 82.0f * kDegrees, {0.0f, 0.0f, 1.0f}) *
                            glm::translate(glm::mat4(1.0f), {0.0f, -0.36f, 0.0f})});
  // The shallow reef's pair (scene_features.h): the same assets, a high sun's focus.
  placements.push_back({"shallow_glass_sphere", "glass_sphere.glb",
                        onSand(kShallowSphereXZ, kShallowSphereHeightAboveSand)});
  placements.push_back({"shallow_metal_ring", "metal_ring.glb",
                        onSand(kShallowRingXZ, 0.04) *
                            glm::rotate(glm::mat4(1.0f), -10.0f * kDegrees, {0.0f, 1.0f, 0.0f})});
  return placements;
}

bool addModels(Model& scene, const std::string& assetDir,
               const std::vector<ModelPlacement>& placements, std::string& error,
               std::vector<std::string>* warnings) {
  Model added;
  for (const ModelPlacement& placement : placements) {
    Model model;
    const std::string path = joinPath(assetDir, placement.fileName);
    std::string notes;
    if (!loadGlb(path, model, error, &notes)) return false;
    if (warnings != nullptr && !notes.empty()) warnings->push_back(path + ": " + notes);
    for (Instance& instance : model.instances) {
      instance.name = placement.name + (instance.name.empty() ? "" : "/" + instance.name);
    }
    appendModel(added, model, placement.transform);
  }
  appendModel(scene, added);
  return true;
}

bool buildDefaultSceneWithModels(const DefaultSceneParams& params, const std::string& assetDir,
                                 Model& out, std::string& error) {
  out = buildDefaultScene(params);
  if (!addModels(out, assetDir, defaultModelPlacements(), error)) {
    out = Model{};
    return false;
  }
  return true;
}

}  // namespace ocean_scene
