#include "scene/asset_models.h"

#include "scene/mesh_builders.h"

namespace ocean_scene {

namespace {

Model single(Mesh mesh, Material material) {
  Model model;
  model.materials.push_back(std::move(material));
  mesh.material = 0;
  const std::string name = mesh.name;
  addMeshInstance(model, std::move(mesh), glm::mat4(1.0f), name);
  return model;
}

Material glass(const std::string& name) {
  Material m;
  m.name = name;
  m.baseColor = glm::vec3(1.0f);
  m.metallic = 0.0f;
  m.roughness = 0.02f;
  m.ior = 1.5f;
  m.transmission = 1.0f;
  return m;
}

}  // namespace

Model makeGlassSphereModel() {
  Mesh mesh = makeIcosphere(4, "glass_sphere");
  constexpr float kRadius = 0.5f;
  for (glm::vec3& p : mesh.positions) p *= kRadius;
  Material m = glass("clear_glass");
  m.thickness = 2.0f * kRadius;
  m.attenuationColor = {0.85f, 0.95f, 0.93f};
  m.attenuationDistance = 1.5f;
  return single(std::move(mesh), m);
}

Model makeMetalRingModel() {
  Mesh mesh = makeTorus(0.35f, 0.05f, 96, 24, "metal_ring");
  Material m;
  m.name = "brass";
  m.baseColor = {0.91f, 0.78f, 0.42f};  // linear reflectance (F0) of brass
  m.metallic = 1.0f;
  m.roughness = 0.2f;
  return single(std::move(mesh), m);
}

Model makeGlassBottleModel() {
  // (radius, y): up the outside, over the lip, down the inside; see makeLathe.
  const std::vector<glm::vec2> profile = {
      {0.0f, 0.0f},     {0.07f, 0.0f},    {0.085f, 0.005f}, {0.09f, 0.015f},  {0.09f, 0.28f},
      {0.085f, 0.31f},  {0.07f, 0.34f},   {0.045f, 0.365f}, {0.025f, 0.38f},  {0.02f, 0.40f},
      {0.02f, 0.44f},   {0.024f, 0.442f}, {0.026f, 0.447f}, {0.024f, 0.452f}, {0.02f, 0.454f},
      {0.016f, 0.452f}, {0.016f, 0.40f},  {0.021f, 0.377f}, {0.042f, 0.361f}, {0.066f, 0.337f},
      {0.081f, 0.308f}, {0.086f, 0.28f},  {0.086f, 0.02f},  {0.08f, 0.01f},   {0.07f, 0.008f},
      {0.0f, 0.008f}};
  Mesh mesh = makeLathe(profile, 64, "glass_bottle");
  Material m = glass("bottle_glass");
  m.ior = 1.52f;
  m.roughness = 0.05f;
  m.thickness = 0.004f;  // wall thickness
  m.attenuationColor = {0.55f, 0.8f, 0.5f};
  m.attenuationDistance = 0.05f;
  return single(std::move(mesh), m);
}

Model makeAmphoraModel() {
  const std::vector<glm::vec2> profile = {
      {0.0f, 0.0f},   {0.03f, 0.01f},  {0.05f, 0.05f}, {0.12f, 0.15f},  {0.17f, 0.28f},
      {0.18f, 0.36f}, {0.16f, 0.46f},  {0.10f, 0.54f}, {0.06f, 0.58f},  {0.05f, 0.62f},
      {0.05f, 0.66f}, {0.065f, 0.67f}, {0.07f, 0.68f}, {0.065f, 0.69f}, {0.045f, 0.69f},
      {0.04f, 0.68f}, {0.04f, 0.63f},  {0.0f, 0.62f}};
  Mesh mesh = makeLathe(profile, 48, "amphora");
  Material m;
  m.name = "terracotta";
  m.baseColor = {0.45f, 0.17f, 0.07f};
  m.metallic = 0.0f;
  m.roughness = 0.85f;
  return single(std::move(mesh), m);
}

std::vector<AssetModel> makeAssetModels() {
  std::vector<AssetModel> assets;
  assets.push_back({"glass_sphere.glb", makeGlassSphereModel()});
  assets.push_back({"metal_ring.glb", makeMetalRingModel()});
  assets.push_back({"glass_bottle.glb", makeGlassBottleModel()});
  assets.push_back({"amphora.glb", makeAmphoraModel()});
  return assets;
}

}  // namespace ocean_scene
