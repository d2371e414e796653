#pragma once
// Small glTF files written by the tests themselves (no committed blobs): a one-triangle model
// as .gltf JSON text with an external or embedded buffer, or wrapped into a .glb container.

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace gltf_test_files {

// Three float positions (0,0,0) (1,0,0) (0,0,-1): 36 bytes.
inline std::vector<unsigned char> trianglePositions() {
  const float p[9] = {0, 0, 0, 1, 0, 0, 0, 0, -1};
  std::vector<unsigned char> bytes(sizeof p);
  std::memcpy(bytes.data(), p, sizeof p);
  return bytes;
}

inline std::vector<unsigned char> bytesOf(const std::vector<float>& values) {
  std::vector<unsigned char> bytes(values.size() * sizeof(float));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return bytes;
}

// base64, for a data: URI.
inline std::string base64(const std::vector<unsigned char>& bytes) {
  static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) |
                            (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                            (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
    out += table[(n >> 18) & 63];
    out += table[(n >> 12) & 63];
    out += i + 1 < bytes.size() ? table[(n >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? table[n & 63] : '=';
  }
  return out;
}

// The parts of a one-triangle glTF that tests vary.
struct TriangleJson {
  std::vector<unsigned char> data = trianglePositions();  // the buffer's bytes
  std::string buffer = "";  // "" = data as a data: URI; else the members besides byteLength
  bool binChunk = false;    // the buffer is a GLB's BIN chunk (no uri)
  std::string accessor = "\"min\": [0, 0, -1], \"max\": [1, 0, 0]";  // extra accessor members
  std::string nodes = "{\"mesh\": 0}";
  std::string sceneNodes = "0";
  std::string primitive = "";  // extra primitive members, e.g. "\"mode\": 5"
  std::string top = "";        // extra top-level members, with a trailing comma
  int count = 3;
  int componentType = 5126;  // FLOAT

  std::string text() const {
    const std::string length = std::to_string(data.size());
    const std::string members =
        binChunk ? ""
        : buffer.empty()
            ? "\"uri\": \"data:application/octet-stream;base64," + base64(data) + "\", "
            : buffer + ", ";
    return "{" + top + "\"asset\": {\"version\": \"2.0\"}, \"buffers\": [{" + members +
           "\"byteLength\": " + length +
           "}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": " + length +
           "}], \"accessors\": [{\"bufferView\": 0, \"componentType\": " +
           std::to_string(componentType) + ", \"count\": " + std::to_string(count) +
           ", \"type\": \"VEC3\"" + (accessor.empty() ? "" : ", ") + accessor +
           "}], \"meshes\": [{\"name\": \"tri\", \"primitives\": [{\"attributes\": "
           "{\"POSITION\": 0}" +
           (primitive.empty() ? "" : ", ") + primitive + "}]}], \"nodes\": [" + nodes +
           "], \"scenes\": [{\"nodes\": [" + sceneNodes + "]}], \"scene\": 0}";
  }
};

// A GLB container: JSON chunk padded with spaces, BIN chunk (if any) padded with zeros.
inline std::vector<unsigned char> glb(std::string json, std::vector<unsigned char> bin) {
  while (json.size() % 4 != 0) json += ' ';
  while (bin.size() % 4 != 0) bin.push_back(0);
  std::vector<unsigned char> out;
  auto u32 = [&out](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out.push_back(static_cast<unsigned char>(v >> (8 * i)));
  };
  const std::uint32_t total =
      12 + 8 + std::uint32_t(json.size()) + (bin.empty() ? 0 : 8 + std::uint32_t(bin.size()));
  u32(0x46546C67u);  // "glTF"
  u32(2);
  u32(total);
  u32(std::uint32_t(json.size()));
  u32(0x4E4F534Au);
  out.insert(out.end(), json.begin(), json.end());
  if (!bin.empty()) {
    u32(std::uint32_t(bin.size()));
    u32(0x004E4942u);
    out.insert(out.end(), bin.begin(), bin.end());
  }
  return out;
}

// The triangle as a .glb with its positions in the BIN chunk.
inline std::vector<unsigned char> triangleGlb(TriangleJson json = {}) {
  json.binChunk = true;
  return glb(json.text(), json.data);
}

// A quad as a triangle strip using most of what the loader reads beyond plain floats: sparse
// positions, KHR_mesh_quantization normals (normalised bytes) and EXT_mesh_gpu_instancing
// (two copies). As a .glb when `binary`, else a .gltf with a data: URI.
inline std::vector<unsigned char> featureRichModel(bool binary) {
  std::vector<unsigned char> data = bytesOf({0, 0, 0, 1, 0, 0, 0, 0, -1, 1, 0, -1});  // 0..48
  for (int v = 0; v < 4; ++v) data.insert(data.end(), {0, 127, 0, 0});                // 48..64
  data.insert(data.end(), {1, 0, 0, 0});                                              // 64..68
  const auto sparseValue = bytesOf({1, 0, 0});                                        // 68..80
  data.insert(data.end(), sparseValue.begin(), sparseValue.end());
  const auto offsets = bytesOf({0, 0, 0, 2, 0, 0});  // 80..104
  data.insert(data.end(), offsets.begin(), offsets.end());
  const std::string buffer =
      binary ? "" : "\"uri\": \"data:application/octet-stream;base64," + base64(data) + "\", ";
  const std::string json =
      "{\"asset\": {\"version\": \"2.0\"}, \"extensionsUsed\": [\"KHR_mesh_quantization\", "
      "\"EXT_mesh_gpu_instancing\"], \"extensionsRequired\": [\"KHR_mesh_quantization\"], "
      "\"buffers\": [{" +
      buffer +
      "\"byteLength\": 104}], \"bufferViews\": [{\"buffer\": 0, \"byteLength\": 48}, "
      "{\"buffer\": 0, \"byteOffset\": 48, \"byteLength\": 16, \"byteStride\": 4}, "
      "{\"buffer\": 0, \"byteOffset\": 64, \"byteLength\": 1}, {\"buffer\": 0, "
      "\"byteOffset\": 68, \"byteLength\": 12}, {\"buffer\": 0, \"byteOffset\": 80, "
      "\"byteLength\": 24}], \"accessors\": [{\"bufferView\": 0, \"componentType\": 5126, "
      "\"count\": 4, \"type\": \"VEC3\", \"min\": [0, 0, -1], \"max\": [1, 0, 0], "
      "\"sparse\": {\"count\": 1, \"indices\": {\"bufferView\": 2, \"componentType\": 5121}, "
      "\"values\": {\"bufferView\": 3}}}, {\"bufferView\": 1, \"componentType\": 5120, "
      "\"normalized\": true, \"count\": 4, \"type\": \"VEC3\"}, {\"bufferView\": 4, "
      "\"componentType\": 5126, \"count\": 2, \"type\": \"VEC3\"}], \"meshes\": "
      "[{\"primitives\": [{\"mode\": 5, \"attributes\": {\"POSITION\": 0, \"NORMAL\": 1}}]}], "
      "\"nodes\": [{\"mesh\": 0, \"extensions\": {\"EXT_mesh_gpu_instancing\": "
      "{\"attributes\": {\"TRANSLATION\": 2}}}}], \"scenes\": [{\"nodes\": [0]}], "
      "\"scene\": 0}";
  return binary ? glb(json, data) : std::vector<unsigned char>(json.begin(), json.end());
}

inline void writeFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
}

inline void writeFile(const std::filesystem::path& path, const std::vector<unsigned char>& bytes) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

// A fresh empty directory under the test temp dir, of this process alone: ctest runs each test
// in a process of its own, in parallel, and a suite's set-up that emptied a shared directory
// deleted another process's files while it read them (SceneGltfCorpus, "cannot open file").
inline std::filesystem::path freshDir(const std::filesystem::path& root, const std::string& name) {
  const auto dir = root / (name + "." + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Whether `s` is well-formed UTF-8 (lead byte, length, continuation bytes), written here
// rather than taken from the loader so that the loader's own escaping is checked independently.
inline bool validUtf8(const std::string& s) {
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const std::size_t n = c < 0x80         ? 1
                          : (c >> 5) == 6  ? 2
                          : (c >> 4) == 14 ? 3
                          : (c >> 3) == 30 ? 4
                                           : 0;
    if (n == 0 || i + n > s.size()) return false;
    for (std::size_t k = 1; k < n; ++k) {
      if ((static_cast<unsigned char>(s[i + k]) & 0xC0) != 0x80) return false;
    }
    i += n;
  }
  return true;
}

}  // namespace gltf_test_files
