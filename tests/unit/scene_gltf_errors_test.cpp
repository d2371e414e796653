// The glTF loader on bad input: each case returns false with a one-line message that names the
// file and the problem, leaves the output empty, and does not crash.
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include "scene/gltf_loader.h"
#include "scene/hash_noise.h"

namespace ocean_scene {
namespace {

std::string tempPath(const std::string& name) {
  return (std::filesystem::path(testing::TempDir()) / ("ocean_scene_bad_" + name)).string();
}

void writeBytes(const std::string& path, const std::vector<unsigned char>& bytes) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(bytes.data()),
             static_cast<std::streamsize>(bytes.size()));
}

std::vector<unsigned char> readBytes(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(file), {});
}

// Expects failure and returns the message after checking its form.
std::string expectLoadFails(const std::string& path) {
  Model model;
  model.meshes.resize(1);  // must be cleared on failure
  std::string error;
  EXPECT_FALSE(loadGlb(path, model, error));
  EXPECT_TRUE(model.meshes.empty() && model.instances.empty() && model.materials.empty());
  EXPECT_EQ(error.rfind(path + ": ", 0), 0u) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  EXPECT_GT(error.size(), path.size() + 4);
  return error;
}

void expectMentions(const std::string& error, const std::string& word) {
  EXPECT_NE(error.find(word), std::string::npos) << "'" << word << "' not in: " << error;
}

// A valid one-triangle model: positions (view 0), normals (view 1), u16 indices (view 2).
struct Triangle {
  std::vector<float> positions = {0, 0, 0, 1, 0, 0, 0, 0, -1};
  std::vector<float> normals = {0, 1, 0, 0, 1, 0, 0, 1, 0};
  std::vector<std::uint16_t> indices = {0, 1, 2, 0};  // padded to 4-byte multiple; count 3

  tinygltf::Model build() const {
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.buffers.resize(1);
    auto& data = m.buffers[0].data;
    auto append = [&](const void* src, std::size_t bytes) {
      tinygltf::BufferView view;
      view.buffer = 0;
      view.byteOffset = data.size();
      view.byteLength = bytes;
      data.resize(data.size() + bytes);
      std::memcpy(data.data() + view.byteOffset, src, bytes);
      m.bufferViews.push_back(view);
    };
    append(positions.data(), positions.size() * sizeof(float));
    append(normals.data(), normals.size() * sizeof(float));
    append(indices.data(), indices.size() * sizeof(std::uint16_t));
    auto accessor = [&](int view, int componentType, int type, std::size_t count) {
      tinygltf::Accessor a;
      a.bufferView = view;
      a.componentType = componentType;
      a.type = type;
      a.count = count;
      m.accessors.push_back(a);
    };
    accessor(0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    accessor(1, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, 3);
    accessor(2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, 3);
    tinygltf::Primitive primitive;
    primitive.attributes["POSITION"] = 0;
    primitive.attributes["NORMAL"] = 1;
    primitive.indices = 2;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    tinygltf::Mesh mesh;
    mesh.name = "tri";
    mesh.primitives.push_back(primitive);
    m.meshes.push_back(mesh);
    tinygltf::Node node;
    node.mesh = 0;
    m.nodes.push_back(node);
    tinygltf::Scene scene;
    scene.nodes = {0};
    m.scenes.push_back(scene);
    m.defaultScene = 0;
    return m;
  }
};

std::string writeModel(const tinygltf::Model& m, const std::string& name) {
  const std::string path = tempPath(name);
  tinygltf::TinyGLTF writer;
  EXPECT_TRUE(writer.WriteGltfSceneToFile(&m, path, true, true, false, true));
  return path;
}

// Writes the valid triangle after `damage` has edited the glTF structure.
std::string writeTriangle(const std::string& name,
                          const std::function<void(tinygltf::Model&)>& damage) {
  tinygltf::Model m = Triangle{}.build();
  damage(m);
  return writeModel(m, name);
}

TEST(SceneGltfErrors, UndamagedTriangleLoads) {
  const std::string path = writeTriangle("ok.glb", [](tinygltf::Model&) {});
  Model model;
  std::string error;
  ASSERT_TRUE(loadGlb(path, model, error)) << error;
  EXPECT_EQ(model.meshes.at(0).indices.size(), 3u);
}

TEST(SceneGltfErrors, MissingFile) {
  expectMentions(expectLoadFails(tempPath("does_not_exist.glb")), "cannot open");
}

TEST(SceneGltfErrors, EmptyFile) {
  const std::string path = tempPath("empty.glb");
  writeBytes(path, {});
  expectMentions(expectLoadFails(path), "empty");
}

TEST(SceneGltfErrors, TruncatedGlb) {
  const std::string good = writeTriangle("to_truncate.glb", [](tinygltf::Model&) {});
  const std::vector<unsigned char> bytes = readBytes(good);
  ASSERT_GT(bytes.size(), 64u);
  for (std::size_t keep : {std::size_t{6}, std::size_t{20}, bytes.size() / 2, bytes.size() - 4}) {
    SCOPED_TRACE(keep);
    const std::string path = tempPath("truncated_" + std::to_string(keep) + ".glb");
    writeBytes(path,
               std::vector<unsigned char>(bytes.begin(), bytes.begin() + static_cast<long>(keep)));
    expectLoadFails(path);
  }
}

TEST(SceneGltfErrors, GarbageBytes) {
  HashRng rng(3);
  std::vector<unsigned char> garbage(4096);
  for (unsigned char& b : garbage) b = static_cast<unsigned char>(rng.nextU32() & 0xffU);
  garbage[0] = 0x7f;  // not '{', not 'g'
  const std::string path = tempPath("garbage.glb");
  writeBytes(path, garbage);
  expectMentions(expectLoadFails(path), "not a glTF");
  // The same garbage behind a valid GLB magic must be rejected by tinygltf's header checks.
  std::memcpy(garbage.data(), "glTF", 4);
  writeBytes(path, garbage);
  expectLoadFails(path);
  // And JSON that is not glTF.
  const std::string json = "{\"hello\": [1, 2, 3]}";
  writeBytes(path, std::vector<unsigned char>(json.begin(), json.end()));
  expectLoadFails(path);
}

TEST(SceneGltfErrors, AccessorOutOfBounds) {
  const std::string path =
      writeTriangle("oob.glb", [](tinygltf::Model& m) { m.accessors[0].count = 1000; });
  const std::string error = expectLoadFails(path);
  expectMentions(error, "accessor 0 (POSITION)");
  expectMentions(error, "out of bounds");
}

TEST(SceneGltfErrors, AccessorOffsetPastView) {
  const std::string path = writeTriangle("offset.glb", [](tinygltf::Model& m) {
    m.accessors[2].byteOffset = 4;  // 3 u16 from byte 4 end at 10 > view length 8
  });
  expectMentions(expectLoadFails(path), "accessor 2 (indices) is out of bounds");
}

TEST(SceneGltfErrors, StrideSmallerThanElement) {
  const std::string path = writeTriangle("stride.glb", [](tinygltf::Model& m) {
    m.bufferViews[0].byteStride = 8;  // VEC3 float is 12 bytes
  });
  expectMentions(expectLoadFails(path), "byteStride 8 is smaller than the element size 12");
}

TEST(SceneGltfErrors, IndexOutOfRange) {
  Triangle triangle;
  triangle.indices = {0, 1, 7, 0};
  const std::string path = writeModel(triangle.build(), "index.glb");
  expectMentions(expectLoadFails(path), "index 7 at position 2 is out of range for 3 vertices");
}

TEST(SceneGltfErrors, NaNPosition) {
  Triangle triangle;
  triangle.positions[4] = std::numeric_limits<float>::quiet_NaN();
  const std::string path = writeModel(triangle.build(), "nan.glb");
  expectMentions(expectLoadFails(path), "(POSITION) contains a non-finite value");
}

TEST(SceneGltfErrors, WrongComponentTypes) {
  const std::string positions = writeTriangle("postype.glb", [](tinygltf::Model& m) {
    m.accessors[0].componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
    m.accessors[0].count = 2;
  });
  // 16-bit positions are KHR_mesh_quantization's; without the extension declared, refused by name.
  expectMentions(expectLoadFails(positions), "does not declare KHR_mesh_quantization");
  const std::string indices = writeTriangle("idxtype.glb", [](tinygltf::Model& m) {
    m.accessors[2].componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    m.accessors[2].count = 2;
  });
  expectMentions(expectLoadFails(indices), "must be UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  const std::string vec2 = writeTriangle("idxvec.glb", [](tinygltf::Model& m) {
    m.accessors[2].type = TINYGLTF_TYPE_VEC2;
    m.accessors[2].count = 1;
  });
  expectMentions(expectLoadFails(vec2), "must be SCALAR");
}

TEST(SceneGltfErrors, AttributeCountsMustMatch) {
  const std::string path =
      writeTriangle("counts.glb", [](tinygltf::Model& m) { m.accessors[1].count = 2; });
  expectMentions(expectLoadFails(path), "NORMAL count 2 differs from POSITION count 3");
}

TEST(SceneGltfErrors, NonTriangleModeRejected) {
  const std::string path = writeTriangle(
      "lines.glb", [](tinygltf::Model& m) { m.meshes[0].primitives[0].mode = TINYGLTF_MODE_LINE; });
  expectMentions(expectLoadFails(path), "mode 1 (lines) is not supported");
}

TEST(SceneGltfErrors, BufferViewPastBufferAndMissingReferences) {
  const std::string view =
      writeTriangle("view.glb", [](tinygltf::Model& m) { m.bufferViews[1].byteLength = 4096; });
  expectLoadFails(view);  // tinygltf or our check, whichever sees it first
  const std::string accessor = writeTriangle(
      "noacc.glb", [](tinygltf::Model& m) { m.meshes[0].primitives[0].attributes["NORMAL"] = 9; });
  expectLoadFails(accessor);
  const std::string material = writeTriangle(
      "nomat.glb", [](tinygltf::Model& m) { m.meshes[0].primitives[0].material = 4; });
  expectLoadFails(material);
  const std::string noPosition = writeTriangle("nopos.glb", [](tinygltf::Model& m) {
    m.meshes[0].primitives[0].attributes.erase("POSITION");
  });
  expectMentions(expectLoadFails(noPosition), "no POSITION");
}

TEST(SceneGltfErrors, BadMaterialValues) {
  const std::string path = writeTriangle("badior.glb", [](tinygltf::Model& m) {
    tinygltf::Material material;
    material.name = "bad";
    material.extensions["KHR_materials_ior"] =
        tinygltf::Value(tinygltf::Value::Object{{"ior", tinygltf::Value(0.5)}});
    m.materials.push_back(material);
    m.meshes[0].primitives[0].material = 0;
  });
  expectMentions(expectLoadFails(path),
                 "material 'bad': KHR_materials_ior ior must be 0 or at least 1");
  const std::string transmission = writeTriangle("badtr.glb", [](tinygltf::Model& m) {
    tinygltf::Material material;
    material.name = "odd";
    material.extensions["KHR_materials_transmission"] =
        tinygltf::Value(tinygltf::Value::Object{{"transmissionFactor", tinygltf::Value(2.0)}});
    m.materials.push_back(material);
    m.meshes[0].primitives[0].material = 0;
  });
  expectMentions(expectLoadFails(transmission), "transmissionFactor outside [0, 1]");
}

TEST(SceneGltfErrors, NodeCycleRejected) {
  const std::string path = writeTriangle("cycle.glb", [](tinygltf::Model& m) {
    tinygltf::Node second;
    second.children = {0};
    m.nodes.push_back(second);
    m.nodes[0].children = {1};
  });
  expectMentions(expectLoadFails(path), "reached twice");
}

}  // namespace
}  // namespace ocean_scene
