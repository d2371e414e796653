// meshopt-compressed glTF (EXT_meshopt_compression): a quad whose positions and
// triangles are encoded here with libmeshoptimizer, behind a fallback buffer that has no data
// (as gltfpack writes them), loads as the quad from .gltf and .glb; malformed compressed views
// are refused by name. No committed blobs.
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gltf_compressed_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
using namespace gltf_compressed_files;

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
  const Compressed c = encodeMeshoptQuad();
  const fs::path d = dir("quad");
  gltf_test_files::writeFile(d / "quad.gltf",
                             meshoptGltf(c, "\"uri\": \"data:application/octet-stream;base64," +
                                                gltf_test_files::base64(c.bytes) + "\""));
  expectQuad(d / "quad.gltf");
  gltf_test_files::writeFile(d / "quad.glb", gltf_test_files::glb(meshoptGltf(c, ""), c.bytes));
  expectQuad(d / "quad.glb");
}

TEST(SceneGltfMeshopt, MalformedCompressedViewsRefusedByName) {
  const Compressed c = encodeMeshoptQuad();
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
  // A count no compressed data that small could hold: refused before anything is allocated.
  text = meshoptGltf(c, uri);
  const std::string view = "\"buffer\": 1, \"byteLength\": 48,", count = "\"count\": 4,";
  text.replace(text.find(view), view.size(), "\"buffer\": 1, \"byteLength\": 960000000,");
  text.replace(text.find(count), count.size(), "\"count\": 80000000,");
  EXPECT_NE(refusal("claim.gltf", text).find("bytes claimed from"), std::string::npos);
  // KHR_meshopt_compression (a different bitstream) is still refused by name.
  text = meshoptGltf(c, uri);
  for (std::size_t at; (at = text.find("\"EXT_meshopt_compression\"]")) != std::string::npos;)
    text.replace(at, 26, "\"KHR_meshopt_compression\"]");
  EXPECT_NE(refusal("khr.gltf", text).find("KHR_meshopt_compression is not supported"),
            std::string::npos);
}

}  // namespace
}  // namespace ocean_scene
