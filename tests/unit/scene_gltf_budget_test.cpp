// The files that multiply their work without bound are refused from their
// own counts before anything is expanded, in well under a second, naming the limit. They are
// generated small here (gltf_hostile_corpus.h); before the budget the first held 13 GB at 120 s
// and the others were killed there.
#include <chrono>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "gltf_hostile_corpus.h"
#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;
namespace corpus = gltf_hostile_corpus;

// Refused, naming `limit`, in under a second (loosely: about 0.1 s on one core in Release).
void expectRefusedQuickly(const std::string& name, const corpus::Bytes& bytes,
                          const std::string& limit) {
  const fs::path d = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_amplify");
  const fs::path path = d / (name + ".gltf");
  gltf_test_files::writeFile(path, bytes);
  Model model;
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  const bool loaded = loadGlb(path.string(), model, error);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_FALSE(loaded) << name;
  EXPECT_TRUE(model.meshes.empty() && model.instances.empty());
  EXPECT_NE(error.find("exceeds the work budget"), std::string::npos) << error;
  EXPECT_NE(error.find(limit), std::string::npos) << error;
  EXPECT_LT(seconds, 1.0) << name;
  std::printf("%s (%.1f MB): refused in %.3f s, %zu characters: %s\n", name.c_str(),
              double(bytes.size()) / 1e6, seconds, error.size(), error.c_str());
}

TEST(SceneGltfBudget, HundredThousandPrimitivesOfOneSphere) {
  expectRefusedQuickly("primitives", corpus::manyPrimitives(100000),
                       "bytes once expanded (buffers, meshes, instances) (limit 1073741824)");
}

TEST(SceneGltfBudget, TenToTheTenInstancedTriangles) {
  expectRefusedQuickly("triangles", corpus::instancedTriangles(250, 4000),
                       "10000000000 triangles after instancing (limit 4194304)");
}

TEST(SceneGltfBudget, AMillionSphereInstances) {
  expectRefusedQuickly("instances", corpus::manyNodes(1000000), "1000000 nodes (limit 65536)");
}

// Below the budget the same files load: it is their size, not their shape, that is refused.
TEST(SceneGltfBudget, SmallerAmplificationsStillLoad) {
  const fs::path d = gltf_test_files::freshDir(fs::path(testing::TempDir()), "ocean_amplify_ok");
  for (const auto& [name, bytes] :
       {std::pair<std::string, corpus::Bytes>{"primitives", corpus::manyPrimitives(1000)},
        std::pair<std::string, corpus::Bytes>{"triangles", corpus::instancedTriangles(2, 100)},
        std::pair<std::string, corpus::Bytes>{"instances", corpus::manyNodes(1000)}}) {
    gltf_test_files::writeFile(d / (name + ".gltf"), bytes);
    Model model;
    std::string error;
    EXPECT_TRUE(loadGlb((d / (name + ".gltf")).string(), model, error)) << error;
  }
}

}  // namespace
}  // namespace ocean_scene
