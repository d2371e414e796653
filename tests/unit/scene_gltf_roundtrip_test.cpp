// glTF: the generated assets load back exactly as built, the default scene gets its models,
// and the loader flattens hierarchies and fills in what a file may leave out.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "scene/asset_models.h"
#include "scene/default_scene.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_writer.h"
#include "scene/mesh_builders.h"

namespace ocean_scene {
namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::path(testing::TempDir()) / ("ocean_scene_" + name)).string();
}

void expectSameMaterial(const Material& a, const Material& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.baseColor, b.baseColor);
  EXPECT_EQ(a.alpha, b.alpha);
  EXPECT_EQ(a.metallic, b.metallic);
  EXPECT_EQ(a.roughness, b.roughness);
  EXPECT_EQ(a.ior, b.ior);
  EXPECT_EQ(a.transmission, b.transmission);
  EXPECT_EQ(a.thickness, b.thickness);
  EXPECT_EQ(a.attenuationColor, b.attenuationColor);
  EXPECT_EQ(a.attenuationDistance, b.attenuationDistance);
}

void expectSameModel(const Model& loaded, const Model& built) {
  ASSERT_EQ(loaded.meshes.size(), built.meshes.size());
  ASSERT_EQ(loaded.materials.size(), built.materials.size());
  ASSERT_EQ(loaded.instances.size(), built.instances.size());
  for (std::size_t m = 0; m < built.meshes.size(); ++m) {
    const Mesh& a = loaded.meshes[m];
    const Mesh& b = built.meshes[m];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.material, b.material);
    ASSERT_EQ(a.positions.size(), b.positions.size());
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(
        std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::vec3)),
        0);
    for (std::size_t i = 0; i < a.normals.size(); ++i) {
      // The loader renormalises, which may move the last bit.
      ASSERT_NEAR(glm::length(a.normals[i] - b.normals[i]), 0.0f, 1e-6f);
    }
  }
  for (std::size_t i = 0; i < built.materials.size(); ++i) {
    expectSameMaterial(loaded.materials[i], built.materials[i]);
  }
  for (std::size_t i = 0; i < built.instances.size(); ++i) {
    EXPECT_EQ(loaded.instances[i].mesh, built.instances[i].mesh);
    EXPECT_EQ(loaded.instances[i].transform, built.instances[i].transform);
  }
}

TEST(SceneGltf, GeneratedAssetsLoadAsBuilt) {
  for (const AssetModel& asset : makeAssetModels()) {
    SCOPED_TRACE(asset.fileName);
    const std::string path = std::string(OCEAN_ASSET_DIR) + "/" + asset.fileName;
    Model loaded;
    std::string error, warnings;
    ASSERT_TRUE(loadGlb(path, loaded, error, &warnings)) << error;
    EXPECT_TRUE(warnings.empty()) << warnings;
    expectSameModel(loaded, asset.model);
    const auto bytes = std::filesystem::file_size(path);
    EXPECT_GT(bytes, 4u * 1024u);
    EXPECT_LT(bytes, 512u * 1024u);
  }
}

TEST(SceneGltf, GlassAndMetalMaterialsCarryTheirExtensions) {
  Model sphere, ring, bottle;
  std::string error;
  ASSERT_TRUE(loadGlb(std::string(OCEAN_ASSET_DIR) + "/glass_sphere.glb", sphere, error)) << error;
  ASSERT_TRUE(loadGlb(std::string(OCEAN_ASSET_DIR) + "/metal_ring.glb", ring, error)) << error;
  ASSERT_TRUE(loadGlb(std::string(OCEAN_ASSET_DIR) + "/glass_bottle.glb", bottle, error)) << error;
  const Material& glass = sphere.materials.at(0);
  EXPECT_FLOAT_EQ(glass.ior, 1.5f);
  EXPECT_FLOAT_EQ(glass.transmission, 1.0f);
  EXPECT_FLOAT_EQ(glass.thickness, 1.0f);
  EXPECT_FLOAT_EQ(glass.attenuationDistance, 1.5f);
  EXPECT_TRUE(glass.isRefractive());
  const Material& brass = ring.materials.at(0);
  EXPECT_FLOAT_EQ(brass.metallic, 1.0f);
  EXPECT_FLOAT_EQ(brass.transmission, 0.0f);
  EXPECT_TRUE(std::isinf(brass.attenuationDistance));
  EXPECT_FLOAT_EQ(bottle.materials.at(0).ior, 1.52f);
  EXPECT_FLOAT_EQ(bottle.materials.at(0).thickness, 0.004f);
}

TEST(SceneGltf, WriterRoundTripsInstancesAndTransforms) {
  Model model;
  Material plain;
  plain.name = "plain";
  plain.metallic = 0.25f;
  model.materials.push_back(plain);
  Mesh box = makeBox(glm::vec3(0.5f), "box");
  const std::uint32_t mesh = addMeshInstance(model, box, glm::mat4(1.0f), "a");
  glm::mat4 moved(1.0f);
  moved[3] = glm::vec4(1.0f, -2.0f, 3.0f, 1.0f);
  moved[0][0] = 2.0f;
  model.instances.push_back(Instance{mesh, moved, "b"});
  const std::string path = tempPath("instances.glb");
  std::string error;
  ASSERT_TRUE(writeGlb(model, path, error)) << error;
  Model loaded;
  ASSERT_TRUE(loadGlb(path, loaded, error)) << error;
  expectSameModel(loaded, model);
  EXPECT_EQ(loaded.instances[1].name, "b");
  EXPECT_EQ(triangleCount(loaded), 24u);
  EXPECT_EQ(vertexCount(loaded), 48u);
}

TEST(SceneGltf, WriterRejectsInvalidModels) {
  Model model;
  Mesh mesh = makeBox(glm::vec3(1.0f), "box");
  mesh.indices[0] = 999;
  model.materials.push_back(Material{});
  addMeshInstance(model, mesh, glm::mat4(1.0f), "box");
  std::string error;
  EXPECT_FALSE(writeGlb(model, tempPath("invalid.glb"), error));
  EXPECT_NE(error.find("index out of range"), std::string::npos) << error;
}

// A parent with TRS and a child with a matrix, a primitive without normals, without indices
// and without a material, written with tinygltf directly.
tinygltf::Model hierarchyModel() {
  tinygltf::Model m;
  m.asset.version = "2.0";
  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
  m.buffers.resize(1);
  m.buffers[0].data.resize(sizeof positions);
  std::memcpy(m.buffers[0].data.data(), positions, sizeof positions);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteLength = sizeof positions;
  m.bufferViews.push_back(view);
  tinygltf::Accessor accessor;
  accessor.bufferView = 0;
  accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
  accessor.type = TINYGLTF_TYPE_VEC3;
  accessor.count = 3;
  accessor.minValues = {0, 0, -1};
  accessor.maxValues = {1, 0, 0};
  m.accessors.push_back(accessor);
  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] = 0;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = "tri";
  mesh.primitives.push_back(primitive);
  m.meshes.push_back(mesh);
  tinygltf::Node parent, child;
  parent.name = "parent";
  parent.translation = {10, 0, 0};
  parent.scale = {2, 2, 2};
  parent.children = {1};
  child.name = "child";
  child.mesh = 0;
  child.matrix = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 5, 0, 1};  // translate y by 5
  m.nodes = {parent, child};
  tinygltf::Scene scene;
  scene.nodes = {0};
  m.scenes.push_back(scene);
  m.defaultScene = 0;
  return m;
}

TEST(SceneGltf, HierarchyIsFlattenedAndMissingDataFilledIn) {
  const tinygltf::Model source = hierarchyModel();
  const std::string path = tempPath("hierarchy.glb");
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&source, path, true, true, false, true));
  Model loaded;
  std::string error;
  ASSERT_TRUE(loadGlb(path, loaded, error)) << error;
  ASSERT_EQ(loaded.instances.size(), 1u);
  const glm::vec4 origin = loaded.instances[0].transform * glm::vec4(0, 0, 0, 1);
  EXPECT_NEAR(origin.x, 10.0f, 1e-6f);
  EXPECT_NEAR(origin.y, 10.0f, 1e-6f);  // child's 5 scaled by the parent's 2
  EXPECT_EQ(loaded.instances[0].name, "child");
  const Mesh& mesh = loaded.meshes.at(0);
  EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2}));
  ASSERT_EQ(mesh.normals.size(), 3u);
  for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(n.y, 1.0f, 1e-6f);  // generated, facing up
  ASSERT_EQ(loaded.materials.size(), 1u);  // the glTF default material
  EXPECT_FLOAT_EQ(loaded.materials[0].metallic, 1.0f);
  EXPECT_FLOAT_EQ(loaded.materials[0].ior, 1.5f);
}

TEST(SceneGltf, AsciiGltfLoadsToo) {
  const tinygltf::Model source = hierarchyModel();
  const std::string path = tempPath("hierarchy.gltf");
  tinygltf::TinyGLTF writer;
  ASSERT_TRUE(writer.WriteGltfSceneToFile(&source, path, true, true, true, false));
  Model loaded;
  std::string error;
  ASSERT_TRUE(loadGlb(path, loaded, error)) << error;
  EXPECT_EQ(loaded.instances.size(), 1u);
}

TEST(SceneGltf, DefaultSceneIncludesTheModelsOnTheSand) {
  DefaultSceneParams params;
  params.seabed.resolution = 64;
  params.farRockCount = 0;
  const Model procedural = buildDefaultScene(params);
  Model scene;
  std::string error;
  ASSERT_TRUE(buildDefaultSceneWithModels(params, OCEAN_ASSET_DIR, scene, error)) << error;
  const auto placements = defaultModelPlacements();
  EXPECT_EQ(scene.instances.size(), procedural.instances.size() + placements.size());
  int refractive = 0;
  for (std::size_t i = procedural.instances.size(); i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    const Mesh& mesh = scene.meshes[instance.mesh];
    if (scene.materials[mesh.material].isRefractive()) ++refractive;
    // Near the origin, or on the shallow reef's sandbank; under the water's wave crests.
    const bool reef = instance.name.rfind("shallow_", 0) == 0;
    const glm::vec2 site = reef ? glm::vec2(kSandbankXZ) : glm::vec2(0.0f);
    for (const glm::vec3& p : mesh.positions) {
      const glm::vec4 w = instance.transform * glm::vec4(p, 1.0f);
      ASSERT_LT(w.y, reef ? -0.8f : -1.0f) << instance.name;
      ASSERT_LT(std::abs(w.x - site.x), reef ? 5.0f : 30.0f) << instance.name;
      ASSERT_LT(std::abs(w.z - site.y), reef ? 5.0f : 30.0f) << instance.name;
      if (reef) {
        ASSERT_GT(w.y, float(seabedHeight(w.x, w.z)) - 0.05f) << instance.name;
      }
    }
  }
  EXPECT_EQ(refractive, 3);  // sphere, bottle and the reef's sphere
}

TEST(SceneGltf, MissingAssetDirectoryFailsCleanly) {
  Model scene;
  std::string error;
  EXPECT_FALSE(buildDefaultSceneWithModels({}, tempPath("no_such_dir"), scene, error));
  EXPECT_NE(error.find("glass_sphere.glb"), std::string::npos) << error;
  EXPECT_TRUE(scene.meshes.empty());
}

}  // namespace
}  // namespace ocean_scene
