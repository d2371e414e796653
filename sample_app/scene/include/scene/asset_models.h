#pragma once
// The small glTF models make_ocean_assets writes (and the tests rebuild in memory to compare
// against what the loader reads back). Mesh space: metres, y up, resting on y = 0 unless
// stated.

#include <string>
#include <vector>

#include "scene/model.h"

namespace ocean_scene {

// Clear glass ball, radius 0.5 m, centred at the origin. IOR 1.5, transmission 1, slight
// blue-green absorption (volume thickness = diameter).
Model makeGlassSphereModel();
// Brass ring lying flat: torus, centre-line radius 0.35 m, tube radius 0.05 m, centred at the
// origin (its bottom is at y = -0.05). Metallic 1.
Model makeMetalRingModel();
// Green glass flask, 0.454 m tall, 0.09 m radius, 4 mm walls: a closed double-walled solid
// (outer and inner surfaces) so refraction can be traced through both.
Model makeGlassBottleModel();
// Terracotta amphora, 0.69 m tall, opaque: a receiver and occluder for the caustics.
Model makeAmphoraModel();

struct AssetModel {
  std::string fileName;  // e.g. "glass_sphere.glb"
  Model model;
};

// All of the above with their file names, in a fixed order.
std::vector<AssetModel> makeAssetModels();

}  // namespace ocean_scene
