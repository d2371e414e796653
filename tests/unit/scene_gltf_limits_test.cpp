// Each limit of the work budget (scene/gltf_limits.h) is named when it is
// exceeded, with the count, the limit and the option that raises it, and raising it lets the
// same file through.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gltf_hostile_corpus.h"
#include "gltf_test_files.h"
#include "gltf_texture_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;

// The feature-rich quad: 1 node, 1 primitive drawn twice (EXT_mesh_gpu_instancing), a strip of
// 2 triangles: 2 instances, 4 triangles after instancing.
fs::path richModel() {
  const fs::path d = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_limits");
  gltf_test_files::writeFile(d / "rich.glb", gltf_test_files::featureRichModel(true));
  return d / "rich.glb";
}

std::string refusal(const fs::path& path, const GltfLimits& limits) {
  Model model;
  std::string error;
  EXPECT_FALSE(loadGlb(path.string(), model, error, nullptr, limits));
  return error;
}

TEST(SceneGltfLimits, EachLimitIsNamedWithItsCount) {
  const fs::path path = richModel();
  GltfLimits limits;
  limits.raiseOption = "--model-limits";
  GltfLimits triangles = limits;
  triangles.triangles = 3;
  EXPECT_NE(refusal(path, triangles)
                .find("4 triangles after instancing (limit 3); refused before it is expanded "
                      "(raise with --model-limits triangles=N)"),
            std::string::npos)
      << refusal(path, triangles);
  GltfLimits instances = limits;
  instances.instances = 1;
  EXPECT_NE(refusal(path, instances).find("2 instances after instancing (limit 1)"),
            std::string::npos);
  GltfLimits nodes = limits;
  nodes.nodes = 0;
  EXPECT_NE(refusal(path, nodes).find("1 nodes (limit 0)"), std::string::npos);
  GltfLimits bytes = limits;
  bytes.bytes = 100;
  EXPECT_NE(
      refusal(path, bytes).find("bytes once expanded (buffers, meshes, instances) (limit 100)"),
      std::string::npos)
      << refusal(path, bytes);
  // Two at once are both named, and the option names both keys.
  GltfLimits both = triangles;
  both.instances = 1;
  EXPECT_NE(refusal(path, both).find("(raise with --model-limits instances=N,triangles=N)"),
            std::string::npos)
      << refusal(path, both);
}

// The JSON's values and the texture pixels decoded are limits like the others: named with the
// count, the limit and the option's key.
TEST(SceneGltfLimits, JsonValuesAndTexturePixelsAreNamed) {
  const fs::path path = richModel();
  GltfLimits values;
  values.raiseOption = "--model-limits";
  values.jsonValues = 100;
  EXPECT_NE(refusal(path, values)
                .find("more than 100 JSON values (limit 100); refused before it is expanded "
                      "(raise with --model-limits json-values=N)"),
            std::string::npos)
      << refusal(path, values);
  const unsigned char grey[3] = {128, 128, 128};
  const fs::path d = path.parent_path();
  gltf_test_files::writeFile(d / "textured.glb",
                             gltf_texture_files::texturedGlb(
                                 gltf_texture_files::png(d / "grey.png", grey), "[1, 1, 1, 1]"));
  GltfLimits pixels;
  pixels.raiseOption = "--model-limits";
  pixels.pixels = 3;  // the image is 2 x 2
  EXPECT_NE(refusal(d / "textured.glb", pixels)
                .find("4 texture pixels to decode, 1 image(s) (limit 3); refused before it is "
                      "expanded (raise with --model-limits pixels=N)"),
            std::string::npos)
      << refusal(d / "textured.glb", pixels);
  pixels.pixels = 4;
  Model model;
  std::string error;
  EXPECT_TRUE(loadGlb((d / "textured.glb").string(), model, error, nullptr, pixels)) << error;
}

TEST(SceneGltfLimits, RaisingTheLimitsLetsTheFileThrough) {
  const fs::path d = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_raise");
  // 20,000 nodes of a 256-triangle sphere: over the instances (16384) and triangles (4M)
  // limits by default.
  gltf_test_files::writeFile(d / "many.gltf", gltf_hostile_corpus::manyNodes(20000));
  Model model;
  std::string error;
  EXPECT_FALSE(loadGlb((d / "many.gltf").string(), model, error));
  GltfLimits raised;
  raised.instances = 20000;
  raised.triangles = 20000 * 256;
  EXPECT_TRUE(loadGlb((d / "many.gltf").string(), model, error, nullptr, raised)) << error;
  EXPECT_EQ(model.instances.size(), 20000u);
}

}  // namespace
}  // namespace ocean_scene
