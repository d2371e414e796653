// meshopt-compressed glTF (EXT_meshopt_compression, issue 17 item 3): a quad whose positions and
// triangles are encoded here with libmeshoptimizer, behind a fallback buffer that has no data
// (as gltfpack writes them), loads as the quad from .gltf and .glb; malformed compressed views
// are refused by name. No committed blobs.
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;

const float kQuad[12] = {0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1};
const unsigned int kTriangles[6] = {0, 1, 2, 2, 1, 3};

struct Compressed {
  std::vector<unsigned char> bytes;  // positions, padded to 4, then indices
  std::size_t positionBytes = 0, indexOffset = 0, indexBytes = 0;
};

Compressed encodeQuad() {
  Compressed out;
  std::vector<unsigned char> v(meshopt_encodeVertexBufferBound(4, 12));
  v.resize(meshopt_encodeVertexBuffer(v.data(), v.size(), kQuad, 4, 12));
  std::vector<unsigned char> i(meshopt_encodeIndexBufferBound(6, 4));
  i.resize(meshopt_encodeIndexBuffer(i.data(), i.size(), kTriangles, 6));
  EXPECT_FALSE(v.empty() || i.empty());
  out.positionBytes = v.size();
  out.bytes = v;
  while (out.bytes.size() % 4 != 0) out.bytes.push_back(0);
  out.indexOffset = out.bytes.size();
  out.indexBytes = i.size();
  out.bytes.insert(out.bytes.end(), i.begin(), i.end());
  return out;
}

// `compressed`: the buffer's members besides byteLength ("" = a GLB's BIN chunk).
// `positionMode`: the positions view's mode (ATTRIBUTES unless a test breaks it).
std::string meshoptGltf(const Compressed& c, const std::string& compressed,
                        const std::string& positionMode = "ATTRIBUTES") {
  const auto n = [](std::size_t v) { return std::to_string(v); };
  return R"({"asset": {"version": "2.0"},
    "extensionsUsed": ["EXT_meshopt_compression"],
    "extensionsRequired": ["EXT_meshopt_compression"],
    "buffers": [{)" +
         compressed + (compressed.empty() ? "" : ", ") + R"("byteLength": )" + n(c.bytes.size()) +
         R"(},
      {"byteLength": 72, "extensions": {"EXT_meshopt_compression": {"fallback": true}}}],
    "bufferViews": [
      {"buffer": 1, "byteLength": 48, "byteStride": 12, "extensions": {"EXT_meshopt_compression":
        {"buffer": 0, "byteLength": )" +
         n(c.positionBytes) + R"(, "byteStride": 12, "count": 4,
         "mode": ")" +
         positionMode + R"("}}},
      {"buffer": 1, "byteOffset": 48, "byteLength": 24, "extensions": {"EXT_meshopt_compression":
        {"buffer": 0, "byteOffset": )" +
         n(c.indexOffset) + R"(, "byteLength": )" + n(c.indexBytes) +
         R"(, "byteStride": 4, "count": 6, "mode": "TRIANGLES"}}}],
    "accessors": [
      {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
       "min": [0, 0, -1], "max": [1, 0, 0]},
      {"bufferView": 1, "componentType": 5125, "count": 6, "type": "SCALAR"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

fs::path dir(const std::string& name) {
  return gltf_test_files::freshDir(fs::path(testing::TempDir()) / "ocean_gltf_meshopt", name);
}

void expectQuad(const fs::path& path) {
  Model model;
  std::string error;
  ASSERT_TRUE(loadGlb(path.string(), model, error)) << error;
  ASSERT_EQ(model.meshes.size(), 1u);
  const Mesh& mesh = model.meshes[0];
  ASSERT_EQ(mesh.positions.size(), 4u);
  for (int v = 0; v < 4; ++v)
    EXPECT_EQ(mesh.positions[v], glm::vec3(kQuad[3 * v], kQuad[3 * v + 1], kQuad[3 * v + 2]));
  EXPECT_EQ(mesh.indices, std::vector<std::uint32_t>(kTriangles, kTriangles + 6));
}

TEST(SceneGltfMeshopt, CompressedQuadLoadsFromGltfAndGlb) {
  const Compressed c = encodeQuad();
  const fs::path d = dir("quad");
  gltf_test_files::writeFile(d / "quad.gltf",
                             meshoptGltf(c, "\"uri\": \"data:application/octet-stream;base64," +
                                                gltf_test_files::base64(c.bytes) + "\""));
  expectQuad(d / "quad.gltf");
  gltf_test_files::writeFile(d / "quad.glb", gltf_test_files::glb(meshoptGltf(c, ""), c.bytes));
  expectQuad(d / "quad.glb");
}

TEST(SceneGltfMeshopt, MalformedCompressedViewsRefusedByName) {
  const Compressed c = encodeQuad();
  const fs::path d = dir("malformed");
  const std::string uri =
      "\"uri\": \"data:application/octet-stream;base64," + gltf_test_files::base64(c.bytes) + "\"";
  const auto refusal = [&](const std::string& name, const std::string& text) {
    gltf_test_files::writeFile(d / name, text);
    Model model;
    std::string error;
    EXPECT_FALSE(loadGlb((d / name).string(), model, error)) << name;
    EXPECT_TRUE(model.meshes.empty());
    return error;
  };
  EXPECT_NE(refusal("mode.gltf", meshoptGltf(c, uri, "SPLINES"))
                .find("bufferView 0 EXT_meshopt_compression: mode 'SPLINES' is not ATTRIBUTES"),
            std::string::npos);
  // Corrupt compressed bytes: the decoder's refusal, named.
  Compressed broken = c;
  for (std::size_t i = 0; i < broken.positionBytes; ++i) broken.bytes[i] = 0xff;
  const std::string brokenUri = "\"uri\": \"data:application/octet-stream;base64," +
                                gltf_test_files::base64(broken.bytes) + "\"";
  EXPECT_NE(refusal("corrupt.gltf", meshoptGltf(broken, brokenUri))
                .find("bufferView 0 EXT_meshopt_compression: data could not be decoded"),
            std::string::npos);
  // A compressed range past its buffer.
  std::string text = meshoptGltf(c, uri);
  const std::string offset = "\"byteOffset\": " + std::to_string(c.indexOffset);
  text.replace(text.find(offset), offset.size(), "\"byteOffset\": 100000");
  EXPECT_NE(refusal("range.gltf", text).find("compressed range lies outside buffer 0"),
            std::string::npos);
  // KHR_meshopt_compression (a different bitstream) is still refused by name.
  text = meshoptGltf(c, uri);
  for (std::size_t at; (at = text.find("\"EXT_meshopt_compression\"]")) != std::string::npos;)
    text.replace(at, 26, "\"KHR_meshopt_compression\"]");
  EXPECT_NE(refusal("khr.gltf", text).find("KHR_meshopt_compression is not supported"),
            std::string::npos);
}

}  // namespace
}  // namespace ocean_scene
