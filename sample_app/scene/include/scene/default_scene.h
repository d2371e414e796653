#pragma once
// The default scene of ocean_sample: procedural seabed, rocks, a pillar, a column, a wall and
// a rock arch (all deterministic, no files), plus glTF models placed on the sand.

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "scene/model.h"
#include "scene/seabed.h"

namespace ocean_scene {

struct DefaultSceneParams {
  SeabedMeshParams seabed;
  int farRockCount = 24;     // scattered 40-120 m from the origin, for the horizon
  int rockSubdivisions = 3;  // 642 vertices per rock
  std::uint32_t seed = 1;    // changes rock shapes and far-rock layout, not the landmarks
};

// Material indices of the procedural scene (a loaded model appends its own after these).
enum DefaultMaterial : std::uint32_t { kSandMaterial = 0, kRockMaterial, kStoneMaterial };

// Deterministic: the same params give bit-identical vertex data on every run.
Model buildDefaultScene(const DefaultSceneParams& params = {});

// A glTF file from the asset directory and where it goes in the scene.
struct ModelPlacement {
  std::string name;      // instance name prefix
  std::string fileName;  // relative to the asset directory, e.g. "glass_sphere.glb"
  glm::mat4 transform{1.0f};
};

// Placements of the generated assets (make_ocean_assets) resting on the sand near the origin;
// positions are in scene_features.h.
std::vector<ModelPlacement> defaultModelPlacements();

// Loads each placement from assetDir through the glTF loader and appends it to scene. Stops at
// the first failure, returning false with the loader's message; scene is then unchanged. The
// loader's notes, when `warnings` is given, are appended as "<path>: <notes>".
bool addModels(Model& scene, const std::string& assetDir,
               const std::vector<ModelPlacement>& placements, std::string& error,
               std::vector<std::string>* warnings = nullptr);

// buildDefaultScene + addModels(defaultModelPlacements()).
bool buildDefaultSceneWithModels(const DefaultSceneParams& params, const std::string& assetDir,
                                 Model& out, std::string& error);

}  // namespace ocean_scene
