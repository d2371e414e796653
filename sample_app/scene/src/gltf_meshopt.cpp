#include "gltf_meshopt.h"

#include <cstdint>
#include <cstdio>
#include <vector>

#include <meshoptimizer.h>

#include "gltf_text.h"
#include "gltf_value.h"

namespace ocean_scene::gltf {

namespace {

constexpr const char* kExtension = "EXT_meshopt_compression";

std::string text(const tinygltf::Value& object, const char* key, const char* fallback) {
  const tinygltf::Value* v = member(object, key);
  return v != nullptr && v->IsString() ? v->Get<std::string>() : std::string(fallback);
}

struct View {
  long long buffer, offset, length, stride, count;
  std::string mode, filter;
};

// Reads e[key] into `out` (`absent` when missing, for optional fields); the problem, naming the
// field and the value found, when it is not a whole number tinygltf kept exactly.
std::string field(const tinygltf::Value& e, const char* key, long long absent, long long& out) {
  const tinygltf::Value* v = member(e, key);
  out = wholeNumber(e, key, absent);
  if (v == nullptr) return absent < 0 ? std::string(key) + " is missing" : "";
  if (!v->IsNumber()) return std::string(key) + " is not a number";
  if (out >= 0) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v->GetNumberAsDouble());
  return std::string(key) + " is " + text + "; it must be a whole number in [0, 2^53]";
}

// The spec's constraints on mode, filter and stride (EXT_meshopt_compression README).
std::string invalid(const View& v) {
  const std::string stride = "byteStride " + std::to_string(v.stride);
  if (v.mode == "ATTRIBUTES") {
    if (v.stride < 4 || v.stride % 4 != 0 || v.stride > 256)
      return stride + ": ATTRIBUTES needs 4..256, a multiple of 4";
  } else if (v.mode == "TRIANGLES") {
    if (v.count % 3 != 0) return "TRIANGLES count must be a multiple of 3";
    if (v.stride != 2 && v.stride != 4) return stride + ": TRIANGLES needs 2 or 4";
  } else if (v.mode == "INDICES") {
    if (v.stride != 2 && v.stride != 4) return stride + ": INDICES needs 2 or 4";
  } else {
    return "mode '" + excerpt(v.mode, 40) + "' is not ATTRIBUTES, TRIANGLES or INDICES";
  }
  if (v.filter != "NONE" && v.mode != "ATTRIBUTES") return "filters apply to ATTRIBUTES only";
  if (v.filter == "OCTAHEDRAL" && v.stride != 4 && v.stride != 8) {
    return stride + ": OCTAHEDRAL needs 4 or 8";
  }
  if (v.filter == "QUATERNION" && v.stride != 8) return stride + ": QUATERNION needs 8";
  if (v.filter != "NONE" && v.filter != "OCTAHEDRAL" && v.filter != "QUATERNION" &&
      v.filter != "EXPONENTIAL") {
    return "filter '" + excerpt(v.filter, 40) + "' is unknown";
  }
  if (std::uint64_t(v.count) > kMaxMeshoptDecodedBytes / std::uint64_t(v.stride)) {
    return "count " + std::to_string(v.count) + " x " + stride + " decodes to more than " +
           std::to_string(kMaxMeshoptDecodedBytes >> 20) + " MiB";
  }
  return "";
}

bool decodeView(tinygltf::Model& model, std::size_t index, std::string& error) {
  tinygltf::BufferView& target = model.bufferViews[index];
  const tinygltf::Value& e = target.extensions.at(kExtension);
  View v{0, 0, 0, 0, 0, text(e, "mode", ""), text(e, "filter", "NONE")};
  const std::string where = "bufferView " + std::to_string(index) + " " + kExtension + ": ";
  std::string problem = field(e, "buffer", -1, v.buffer);
  if (problem.empty()) problem = field(e, "byteOffset", 0, v.offset);
  if (problem.empty()) problem = field(e, "byteLength", -1, v.length);
  if (problem.empty()) problem = field(e, "byteStride", -1, v.stride);
  if (problem.empty()) problem = field(e, "count", -1, v.count);
  if (problem.empty()) problem = invalid(v);
  if (!problem.empty()) {
    error = where + problem;
    return false;
  }
  if (static_cast<std::size_t>(v.buffer) >= model.buffers.size()) {
    error = where + "buffer " + std::to_string(v.buffer) + " does not exist";
    return false;
  }
  const std::vector<unsigned char>& source = model.buffers[std::size_t(v.buffer)].data;
  if (std::uint64_t(v.offset) > source.size() ||
      std::uint64_t(v.length) > source.size() - std::uint64_t(v.offset)) {
    error = where + "compressed range lies outside buffer " + std::to_string(v.buffer);
    return false;
  }
  const std::size_t bytes = std::size_t(v.count) * std::size_t(v.stride);
  if (target.byteLength != bytes) {
    error = where + "count x byteStride (" + std::to_string(bytes) +
            ") differs from the bufferView's byteLength " + std::to_string(target.byteLength);
    return false;
  }
  if (bytes / kMaxMeshoptRatio > std::size_t(v.length) + 64) {
    error = where + std::to_string(bytes) + " bytes claimed from " + std::to_string(v.length) +
            " compressed, more than meshopt can encode";
    return false;
  }
  std::vector<unsigned char> decoded(bytes);
  const unsigned char* data = source.data() + v.offset;
  const std::size_t count = std::size_t(v.count), stride = std::size_t(v.stride);
  const int status =
      v.mode == "ATTRIBUTES"
          ? meshopt_decodeVertexBuffer(decoded.data(), count, stride, data, std::size_t(v.length))
      : v.mode == "TRIANGLES"
          ? meshopt_decodeIndexBuffer(decoded.data(), count, stride, data, std::size_t(v.length))
          : meshopt_decodeIndexSequence(decoded.data(), count, stride, data, std::size_t(v.length));
  if (status != 0) {
    error =
        where + "data could not be decoded (meshoptimizer error " + std::to_string(status) + ")";
    return false;
  }
  if (v.filter == "OCTAHEDRAL") meshopt_decodeFilterOct(decoded.data(), count, stride);
  if (v.filter == "QUATERNION") meshopt_decodeFilterQuat(decoded.data(), count, stride);
  if (v.filter == "EXPONENTIAL") meshopt_decodeFilterExp(decoded.data(), count, stride);
  tinygltf::Buffer plain;
  plain.name = "meshopt-decoded bufferView " + std::to_string(index);
  plain.data = std::move(decoded);
  model.buffers.push_back(std::move(plain));
  target.buffer = static_cast<int>(model.buffers.size() - 1);
  target.byteOffset = 0;
  return true;
}

}  // namespace

bool decodeMeshoptViews(tinygltf::Model& model, const std::set<std::size_t>& fallbacks,
                        std::string& error) {
  const std::size_t views = model.bufferViews.size();
  for (std::size_t i = 0; i < views; ++i) {
    if (model.bufferViews[i].extensions.count(kExtension) == 0) continue;
    if (!decodeView(model, i, error)) return false;
  }
  for (std::size_t i = 0; i < views; ++i) {
    const int buffer = model.bufferViews[i].buffer;
    if (buffer >= 0 && fallbacks.count(std::size_t(buffer)) > 0) {
      error = "bufferView " + std::to_string(i) + " reads meshopt fallback buffer " +
              std::to_string(buffer) + ", which has no data, without " + kExtension;
      return false;
    }
  }
  return true;
}

}  // namespace ocean_scene::gltf
