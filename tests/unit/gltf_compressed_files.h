#pragma once
// Small compressed glTF files encoded by the tests themselves with the libraries the loader
// decodes with (no committed blobs): the quad (0,0,0) (1,0,0) (0,0,-1) (1,0,-1) through Draco
// (KHR_draco_mesh_compression) and through meshopt (EXT_meshopt_compression). Used by their
// feature tests and as fuzz seeds.

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <draco/compression/encode.h>
#include <draco/mesh/triangle_soup_mesh_builder.h>
#include <meshoptimizer.h>

#include "gltf_test_files.h"

namespace gltf_compressed_files {

struct DracoQuad {
  std::vector<unsigned char> bytes;
  int positionId = -1, normalId = -1;
  int points = 0;
};

// The quad (0,0,0) (1,0,0) (0,0,-1) (1,0,-1), normals +y, positions quantised to 14 bits.
inline DracoQuad encodeDracoQuad() {
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
  if (!encoder.EncodeMeshToBuffer(*mesh, &buffer).ok()) return {};
  DracoQuad out;
  out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
  out.positionId = int(mesh->attribute(position)->unique_id());
  out.normalId = int(mesh->attribute(normal)->unique_id());
  out.points = int(mesh->num_points());
  return out;
}

// A glTF whose one primitive is the Draco quad: accessors with counts and bounds but no
// bufferView, the compressed bytes in a data: URI.
inline std::string dracoGltf(const DracoQuad& quad, int pointCount, const std::string& bounds) {
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

inline const std::string kBounds = R"("min": [0, 0, -1], "max": [1, 0, 0])";

inline const float kQuad[12] = {0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1};
inline const unsigned int kTriangles[6] = {0, 1, 2, 2, 1, 3};

struct Compressed {
  std::vector<unsigned char> bytes;  // positions, padded to 4, then indices
  std::size_t positionBytes = 0, indexOffset = 0, indexBytes = 0;
};

inline Compressed encodeMeshoptQuad() {
  Compressed out;
  std::vector<unsigned char> v(meshopt_encodeVertexBufferBound(4, 12));
  v.resize(meshopt_encodeVertexBuffer(v.data(), v.size(), kQuad, 4, 12));
  std::vector<unsigned char> i(meshopt_encodeIndexBufferBound(6, 4));
  i.resize(meshopt_encodeIndexBuffer(i.data(), i.size(), kTriangles, 6));
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
inline std::string meshoptGltf(const Compressed& c, const std::string& compressed,
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

}  // namespace gltf_compressed_files
