// glTF features the loader reads beyond plain float triangle lists, and a
// valid file that hides a node with scale 0 (item 2). Files are generated here.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
using gltf_test_files::TriangleJson;
using gltf_test_files::writeFile;

fs::path dir(const std::string& name) {
  return gltf_test_files::freshDir(fs::path(testing::TempDir()) / "ocean_gltf_features", name);
}

Model load(const fs::path& path, std::string* warnings = nullptr) {
  Model model;
  std::string error;
  EXPECT_TRUE(loadGlb(path.string(), model, error, warnings)) << error;
  return model;
}

std::string refusal(const fs::path& path) {
  Model model;
  std::string error;
  EXPECT_FALSE(loadGlb(path.string(), model, error));
  return error;
}

// Four vertices of a quad: (0,0,0) (1,0,0) (0,0,-1) (1,0,-1).
TriangleJson quad(int mode) {
  TriangleJson json;
  json.data = gltf_test_files::bytesOf({0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1});
  json.count = 4;
  json.accessor = "\"min\": [0, 0, -1], \"max\": [1, 0, 0]";
  json.primitive = "\"mode\": " + std::to_string(mode);
  return json;
}

// Spec 3.7.2.1: strip triangle i is (i, i+1+i%2, i+2-i%2), so (0,1,2) (1,3,2): the shared
// edge runs 1->2 in one and 2->1 in the other, the same winding. Fan: (1,2,0) (2,3,0).
TEST(SceneGltfFeatures, StripsAndFansBecomeTriangleLists) {
  const fs::path d = dir("modes");
  writeFile(d / "strip.gltf", quad(5).text());
  writeFile(d / "fan.gltf", quad(6).text());
  const Model strip = load(d / "strip.gltf");
  const Model fan = load(d / "fan.gltf");
  ASSERT_EQ(strip.meshes.size(), 1u);
  ASSERT_EQ(fan.meshes.size(), 1u);
  EXPECT_EQ(strip.meshes[0].indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(fan.meshes[0].indices, (std::vector<std::uint32_t>{1, 2, 0, 2, 3, 0}));
  TriangleJson points = quad(0);
  writeFile(d / "points.gltf", points.text());
  EXPECT_NE(refusal(d / "points.gltf").find("mode 0 (points) is not supported"), std::string::npos);
}

TEST(SceneGltfFeatures, QuantizedPositionsDecoded) {
  const fs::path d = dir("quantized");
  // Normalised unsigned shorts: 65535 is 1.0. Elements padded to 8 bytes (4-byte aligned).
  const std::uint16_t raw[12] = {0, 0, 0, 0, 65535, 0, 0, 0, 0, 0, 65535, 0};
  TriangleJson json;
  json.data.resize(sizeof raw);
  std::memcpy(json.data.data(), raw, sizeof raw);
  json.componentType = 5123;
  json.accessor = "\"normalized\": true, \"min\": [0, 0, 0], \"max\": [65535, 0, 65535]";
  json.top =
      "\"extensionsUsed\": [\"KHR_mesh_quantization\"], "
      "\"extensionsRequired\": [\"KHR_mesh_quantization\"], ";
  std::string text = json.text();
  text.replace(text.find("\"byteLength\": 24}], \"accessors\""), 16,
               "\"byteLength\": 24, \"byteStride\": 8");
  writeFile(d / "q.gltf", text);
  const Model model = load(d / "q.gltf");
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].positions.at(1), glm::vec3(1, 0, 0));
  EXPECT_EQ(model.meshes[0].positions.at(2), glm::vec3(0, 0, 1));
}

// An accessor with no bufferView is zeros plus its sparse values.
TEST(SceneGltfFeatures, SparseAccessorsApplied) {
  const fs::path d = dir("sparse");
  std::vector<unsigned char> data = {1, 2, 0, 0};  // u8 sparse indices, padded
  const auto values = gltf_test_files::bytesOf({1, 0, 0, 0, 0, -1});
  data.insert(data.end(), values.begin(), values.end());
  const std::string text =
      "{\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": "
      "\"data:application/octet-stream;base64," +
      gltf_test_files::base64(data) + "\", \"byteLength\": " + std::to_string(data.size()) +
      "}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 2}, {\"buffer\": 0, \"byteOffset\": "
      "4, \"byteLength\": 24}], \"accessors\": [{\"componentType\": 5126, \"count\": 3, "
      "\"type\": \"VEC3\", \"min\": [0, 0, -1], \"max\": [1, 0, 0], \"sparse\": {\"count\": 2, "
      "\"indices\": {\"bufferView\": 0, \"componentType\": 5121}, \"values\": {\"bufferView\": "
      "1}}}], \"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}], \"nodes\": "
      "[{\"mesh\": 0}], \"scenes\": [{\"nodes\": [0]}], \"scene\": 0}";
  writeFile(d / "s.gltf", text);
  const Model model = load(d / "s.gltf");
  ASSERT_EQ(model.meshes.size(), 1u);
  EXPECT_EQ(model.meshes[0].positions.at(0), glm::vec3(0, 0, 0));
  EXPECT_EQ(model.meshes[0].positions.at(1), glm::vec3(1, 0, 0));
  EXPECT_EQ(model.meshes[0].positions.at(2), glm::vec3(0, 0, -1));
  // Indices that are not increasing are refused.
  std::string unordered = text;
  data[0] = 2;
  data[1] = 1;
  unordered.replace(unordered.find("base64,") + 7, gltf_test_files::base64(data).size(),
                    gltf_test_files::base64(data));
  writeFile(d / "unordered.gltf", unordered);
  EXPECT_NE(refusal(d / "unordered.gltf").find("not increasing"), std::string::npos);
}

// EXT_mesh_gpu_instancing: one node, one instance per TRANSLATION element.
TEST(SceneGltfFeatures, GpuInstancingGivesOneInstancePerCopy) {
  const fs::path d = dir("instancing");
  std::vector<unsigned char> data = gltf_test_files::trianglePositions();
  const auto offsets = gltf_test_files::bytesOf({0, 0, 0, 5, 0, 0, 0, 3, 0});
  data.insert(data.end(), offsets.begin(), offsets.end());
  const auto file = [&](const std::string& extra) {
    return "{" + extra +
           "\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{\"uri\": "
           "\"data:application/octet-stream;base64," +
           gltf_test_files::base64(data) +
           "\", \"byteLength\": 72}], \"bufferViews\": "
           "[{\"buffer\": 0, \"byteLength\": 36}, {\"buffer\": 0, \"byteOffset\": 36, "
           "\"byteLength\": 36}], \"accessors\": [{\"bufferView\": 0, \"componentType\": "
           "5126, \"count\": 3, \"type\": \"VEC3\", \"min\": [0, 0, -1], \"max\": [1, 0, 0]}, "
           "{\"bufferView\": 1, \"componentType\": 5126, \"count\": 3, \"type\": \"VEC3\"}], "
           "\"meshes\": [{\"primitives\": [{\"attributes\": {\"POSITION\": 0}}]}], "
           "\"nodes\": [{\"mesh\": 0, \"translation\": [0, 10, 0], \"extensions\": "
           "{\"EXT_mesh_gpu_instancing\": {\"attributes\": {\"TRANSLATION\": 1}}}}], "
           "\"scenes\": [{\"nodes\": [0]}], \"scene\": 0}";
  };
  writeFile(d / "i.gltf", file("\"extensionsUsed\": [\"EXT_mesh_gpu_instancing\"], "));
  const Model model = load(d / "i.gltf");
  ASSERT_EQ(model.instances.size(), 3u);
  EXPECT_EQ(glm::vec3(model.instances[0].transform[3]), glm::vec3(0, 10, 0));
  EXPECT_EQ(glm::vec3(model.instances[1].transform[3]), glm::vec3(5, 10, 0));
  EXPECT_EQ(glm::vec3(model.instances[2].transform[3]), glm::vec3(0, 13, 0));
}

// Everything at once, as the fuzz test's richest seed: sparse positions, normalised-byte normals,
// a strip and two instanced copies.
TEST(SceneGltfFeatures, FeatureRichModelLoadsAsTextAndBinary) {
  const fs::path d = dir("rich");
  for (bool binary : {false, true}) {
    const fs::path path = d / (binary ? "rich.glb" : "rich.gltf");
    writeFile(path, gltf_test_files::featureRichModel(binary));
    const Model model = load(path);
    ASSERT_EQ(model.instances.size(), 2u);
    ASSERT_EQ(model.meshes.size(), 1u);
    EXPECT_EQ(model.meshes[0].indices.size(), 6u);
    EXPECT_EQ(model.meshes[0].positions.at(1), glm::vec3(1, 0, 0));
    EXPECT_EQ(model.meshes[0].normals.at(0), glm::vec3(0, 1, 0));
    EXPECT_EQ(model.instances[1].transform[3].x, 2.0f);
  }
}

// Scale 0 is a common way to hide a node: it is left out with a note naming it, and the rest
// of the file loads.
TEST(SceneGltfFeatures, HiddenNodeLeftOutWithANote) {
  const fs::path d = dir("hidden");
  TriangleJson json;
  json.nodes = R"({"mesh": 0}, {"mesh": 0, "name": "hidden_lid", "scale": [0, 0, 0]})";
  json.sceneNodes = "0, 1";
  writeFile(d / "h.gltf", json.text());
  std::string warnings;
  const Model model = load(d / "h.gltf", &warnings);
  EXPECT_EQ(model.instances.size(), 1u);
  EXPECT_NE(warnings.find("node 1 'hidden_lid' left out: its transform is not invertible"),
            std::string::npos)
      << warnings;
  // Only hidden nodes: nothing to show is an error.
  json.nodes = R"({"mesh": 0, "scale": [1, 0, 1]})";
  json.sceneNodes = "0";
  writeFile(d / "all_hidden.gltf", json.text());
  EXPECT_NE(refusal(d / "all_hidden.gltf").find("every node with a mesh is hidden"),
            std::string::npos);
}

// The glass extensions as the specs allow them. KHR_materials_ior 0 is the
// spec's infinite IOR (it loads; the sample makes it a mirror), KHR_materials_dispersion is
// read, and textures the sample does not use are named in a note instead of passing silently.
TEST(SceneGltfFeatures, GlassExtensionsAndIgnoredTexturesNoted) {
  const fs::path d = dir("glass");
  TriangleJson json;
  json.primitive = "\"material\": 0";
  json.top = R"("textures": [{}], "materials": [{"name": "prism",
      "pbrMetallicRoughness": {"baseColorFactor": [1, 0.2, 0.2, 1], "metallicFactor": 0,
      "baseColorTexture": {"index": 0}},
      "extensions": {"KHR_materials_transmission": {"transmissionFactor": 1,
      "transmissionTexture": {"index": 0}}, "KHR_materials_ior": {"ior": 0},
      "KHR_materials_dispersion": {"dispersion": 0.36}}}], )";
  writeFile(d / "prism.gltf", json.text());
  std::string warnings;
  const Model model = load(d / "prism.gltf", &warnings);
  ASSERT_EQ(model.materials.size(), 1u);
  EXPECT_EQ(model.materials[0].ior, 0.0f);
  EXPECT_FLOAT_EQ(model.materials[0].dispersion, 0.36f);
  // A whole sentence, saying why the base colour's texture was not used.
  EXPECT_NE(warnings.find("material 'prism': shaded from its factors, without baseColorTexture "
                          "(its texture has no image), "
                          "KHR_materials_transmission.transmissionTexture"),
            std::string::npos)
      << warnings;
  // Between 0 and 1 the spec allows nothing; a negative dispersion neither.
  std::string text = json.text();
  const std::string iorZero = "\"ior\": 0}";
  text.replace(text.find(iorZero), iorZero.size(), "\"ior\": 0.5}");
  writeFile(d / "half.gltf", text);
  EXPECT_NE(refusal(d / "half.gltf").find("ior must be 0 or at least 1"), std::string::npos);
  text = json.text();
  text.replace(text.find("0.36"), 4, "-0.1");
  writeFile(d / "negative.gltf", text);
  EXPECT_NE(refusal(d / "negative.gltf").find("KHR_materials_dispersion below 0"),
            std::string::npos);
}

}  // namespace
}  // namespace ocean_scene
