// Draco-compressed glTF (KHR_draco_mesh_compression): a quad encoded here with
// libdraco's encoder loads as the quad, and a compressed primitive that disagrees with its own
// accessors (point count, bounds) is refused by name. No committed blobs.
#include <algorithm>
#include <filesystem>
#include <memory>
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
  return gltf_test_files::freshDir(fs::path(testing::TempDir()) / "ocean_gltf_draco", name);
}

TEST(SceneGltfDraco, EncodedQuadLoadsAsTheQuad) {
  const DracoQuad quad = encodeDracoQuad();
  ASSERT_FALSE(quad.bytes.empty());
  const fs::path path = dir("quad") / "quad.gltf";
  gltf_test_files::writeFile(path, dracoGltf(quad, quad.points, kBounds));
  Model model;
  std::string error, warnings;
  ASSERT_TRUE(loadGlb(path.string(), model, error, &warnings)) << error;
  ASSERT_EQ(model.meshes.size(), 1u);
  const Mesh& mesh = model.meshes[0];
  ASSERT_EQ(mesh.indices.size(), 6u);
  EXPECT_EQ(mesh.positions.size(), std::size_t(quad.points));
  // Both triangles, the quad's area (1 m^2) and its corners to 14-bit quantisation.
  double area = 0.0;
  for (int t = 0; t < 2; ++t) {
    const glm::vec3 a = mesh.positions[mesh.indices[3 * t]];
    const glm::vec3 b = mesh.positions[mesh.indices[3 * t + 1]];
    const glm::vec3 c = mesh.positions[mesh.indices[3 * t + 2]];
    area += 0.5 * double(glm::length(glm::cross(b - a, c - a)));
  }
  EXPECT_NEAR(area, 1.0, 1e-3);
  for (const glm::vec3& corner :
       {glm::vec3(0, 0, 0), glm::vec3(1, 0, 0), glm::vec3(0, 0, -1), glm::vec3(1, 0, -1)}) {
    const bool found =
        std::any_of(mesh.positions.begin(), mesh.positions.end(),
                    [&](const glm::vec3& p) { return glm::length(p - corner) < 1e-3f; });
    EXPECT_TRUE(found) << corner.x << " " << corner.z;
  }
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const glm::vec3& normal : mesh.normals) EXPECT_NEAR(normal.y, 1.0f, 1e-3f);
  EXPECT_EQ(warnings.find("normals regenerated"), std::string::npos) << warnings;
}

TEST(SceneGltfDraco, CompressedDataThatContradictsItsAccessorsIsRefused) {
  const DracoQuad quad = encodeDracoQuad();
  const fs::path d = dir("contradictions");
  Model model;
  std::string error;
  gltf_test_files::writeFile(d / "count.gltf", dracoGltf(quad, quad.points + 1, kBounds));
  EXPECT_FALSE(loadGlb((d / "count.gltf").string(), model, error));
  EXPECT_NE(error.find("KHR_draco_mesh_compression decodes " + std::to_string(quad.points) +
                       " points, the POSITION accessor says " + std::to_string(quad.points + 1)),
            std::string::npos)
      << error;
  // Bounds a tenth of the quad: its decoded corners lie outside them.
  gltf_test_files::writeFile(
      d / "bounds.gltf",
      dracoGltf(quad, quad.points, R"("min": [0, 0, -0.1], "max": [0.1, 0, 0])"));
  EXPECT_FALSE(loadGlb((d / "bounds.gltf").string(), model, error));
  EXPECT_NE(error.find("POSITION values lie outside the accessor's min/max"), std::string::npos)
      << error;
  EXPECT_TRUE(model.meshes.empty());
  // Truncated compressed data.
  DracoQuad cut = quad;
  cut.bytes.resize(cut.bytes.size() / 2);
  gltf_test_files::writeFile(d / "cut.gltf", dracoGltf(cut, quad.points, kBounds));
  EXPECT_FALSE(loadGlb((d / "cut.gltf").string(), model, error));
  EXPECT_NE(error.find("KHR_draco_mesh_compression data could not be decoded"), std::string::npos)
      << error;
}

}  // namespace
}  // namespace ocean_scene
