// Draco-compressed glTF (KHR_draco_mesh_compression, issue 17 item 3): a quad encoded here with
// libdraco's encoder loads as the quad, and a compressed primitive that disagrees with its own
// accessors (point count, bounds) is refused by name. No committed blobs.
#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <gtest/gtest.h>

#include "gltf_test_files.h"
#include "scene/gltf_loader.h"

namespace ocean_scene {
namespace {

namespace fs = std::filesystem;

struct DracoQuad {
  std::vector<unsigned char> bytes;
  int positionId = -1, normalId = -1;
  int points = 0;
};

// The quad (0,0,0) (1,0,0) (0,0,-1) (1,0,-1), normals +y, positions quantised to 14 bits.
DracoQuad encodeQuad() {
  draco::TriangleSoupMeshBuilder builder;
  builder.Start(2);
  const int position =
      builder.AddAttribute(draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32);
  const int normal = builder.AddAttribute(draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32);
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 0, -1}, {1, 0, -1}};
  const float n[3] = {0, 1, 0};
  builder.SetAttributeValuesForFace(position, draco::FaceIndex(0), p[0], p[1], p[2]);
  builder.SetAttributeValuesForFace(position, draco::FaceIndex(1), p[2], p[1], p[3]);
  for (int f = 0; f < 2; ++f)
    builder.SetAttributeValuesForFace(normal, draco::FaceIndex(f), n, n, n);
  std::unique_ptr<draco::Mesh> mesh = builder.Finalize();
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  draco::EncoderBuffer buffer;
  EXPECT_TRUE(encoder.EncodeMeshToBuffer(*mesh, &buffer).ok());
  DracoQuad out;
  out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
  out.positionId = int(mesh->attribute(position)->unique_id());
  out.normalId = int(mesh->attribute(normal)->unique_id());
  out.points = int(mesh->num_points());
  return out;
}

// A glTF whose one primitive is the Draco quad: accessors with counts and bounds but no
// bufferView, the compressed bytes in a data: URI.
std::string dracoGltf(const DracoQuad& quad, int pointCount, const std::string& bounds) {
  const std::string n = std::to_string(pointCount);
  return R"({"asset": {"version": "2.0"},
    "extensionsUsed": ["KHR_draco_mesh_compression"],
    "extensionsRequired": ["KHR_draco_mesh_compression"],
    "buffers": [{"uri": "data:application/octet-stream;base64,)" +
         gltf_test_files::base64(quad.bytes) + R"(", "byteLength": )" +
         std::to_string(quad.bytes.size()) + R"(}],
    "bufferViews": [{"buffer": 0, "byteLength": )" +
         std::to_string(quad.bytes.size()) + R"(}],
    "accessors": [
      {"componentType": 5126, "count": )" +
         n + R"(, "type": "VEC3", )" + bounds + R"(},
      {"componentType": 5126, "count": )" +
         n + R"(, "type": "VEC3"},
      {"componentType": 5125, "count": 6, "type": "SCALAR"}],
    "meshes": [{"name": "quad", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1},
      "indices": 2, "extensions": {"KHR_draco_mesh_compression": {"bufferView": 0,
      "attributes": {"POSITION": )" +
         std::to_string(quad.positionId) + R"(, "NORMAL": )" + std::to_string(quad.normalId) +
         R"(}}}}]}],
    "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})";
}

const std::string kBounds = R"("min": [0, 0, -1], "max": [1, 0, 0])";

fs::path dir(const std::string& name) {
  return gltf_test_files::freshDir(fs::path(testing::TempDir()) / "ocean_gltf_draco", name);
}

TEST(SceneGltfDraco, EncodedQuadLoadsAsTheQuad) {
  const DracoQuad quad = encodeQuad();
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
  const DracoQuad quad = encodeQuad();
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
