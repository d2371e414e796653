#include "gltf_draco.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <draco/compression/decode.h>
#include <draco/mesh/mesh.h>

#include "gltf_text.h"
#include "gltf_value.h"

namespace ocean_scene::gltf {

namespace {

constexpr const char* kExtension = "KHR_draco_mesh_compression";

bool readAttribute(const draco::Mesh& mesh, const tinygltf::Value& attributes, const char* name,
                   std::vector<glm::vec3>& out, std::string& error) {
  const long long id = wholeNumber(attributes, name, -1);
  if (id < 0) {
    error = std::string(kExtension) + " maps no " + name + " attribute";
    return false;
  }
  const draco::PointAttribute* attribute =
      id > 0xffffffffLL ? nullptr : mesh.GetAttributeByUniqueId(std::uint32_t(id));
  if (attribute == nullptr || attribute->num_components() != 3) {
    error = std::string(kExtension) + " " + name + " attribute " + std::to_string(id) +
            " is missing from the compressed data or is not 3-component";
    return false;
  }
  out.resize(mesh.num_points());
  for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
    float v[3];
    if (!attribute->ConvertValue<float, 3>(attribute->mapped_index(p), v)) {
      error = std::string(kExtension) + " " + name + " values cannot be read as floats";
      return false;
    }
    out[p.value()] = glm::vec3(v[0], v[1], v[2]);
  }
  return true;
}

// Quantised positions may overshoot the exporter's bounds by a quantisation step: the
// tolerance is that step at Draco's coarsest useful setting (8 bits) over the accessor's extent.
bool insideBounds(const tinygltf::Accessor& accessor, const std::vector<glm::vec3>& positions) {
  if (accessor.minValues.size() != 3 || accessor.maxValues.size() != 3) return true;
  for (const glm::vec3& p : positions) {
    for (int a = 0; a < 3; ++a) {
      const double lo = accessor.minValues[std::size_t(a)], hi = accessor.maxValues[std::size_t(a)];
      const double slack = (hi - lo) / 255.0 + 1e-6 * std::max(std::abs(lo), std::abs(hi));
      const double v = p[a];
      if (!(v >= lo - slack && v <= hi + slack)) return false;
    }
  }
  return true;
}

}  // namespace

bool isDracoPrimitive(const tinygltf::Primitive& primitive) {
  return primitive.extensions.count(kExtension) > 0;
}

bool decodeDracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                          std::vector<std::uint32_t>& indices, std::string& error) {
  const tinygltf::Value& extension = primitive.extensions.at(kExtension);
  const long long view = wholeNumber(extension, "bufferView", -1);
  const tinygltf::Value* attributes = member(extension, "attributes");
  if (view < 0 || view >= static_cast<long long>(model.bufferViews.size()) ||
      attributes == nullptr || !attributes->IsObject()) {
    error = std::string(kExtension) + " needs a valid bufferView and an attributes object";
    return false;
  }
  const tinygltf::BufferView& bv = model.bufferViews[std::size_t(view)];
  if (bv.buffer < 0 || static_cast<std::size_t>(bv.buffer) >= model.buffers.size()) {
    error = std::string(kExtension) + " bufferView " + std::to_string(view) + " has no buffer";
    return false;
  }
  const std::vector<unsigned char>& data = model.buffers[std::size_t(bv.buffer)].data;
  if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset) {
    error = std::string(kExtension) + " bufferView " + std::to_string(view) +
            " lies outside its buffer";
    return false;
  }
  draco::DecoderBuffer buffer;
  buffer.Init(reinterpret_cast<const char*>(data.data() + bv.byteOffset), bv.byteLength);
  draco::Decoder decoder;
  auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
  if (!decoded.ok() || decoded.value() == nullptr) {
    error = std::string(kExtension) + " data could not be decoded" +
            (decoded.ok() ? std::string() : ": " + excerpt(decoded.status().error_msg_string()));
    return false;
  }
  const draco::Mesh& mesh = *decoded.value();

  const auto positionAccessor = primitive.attributes.find("POSITION");
  if (positionAccessor == primitive.attributes.end() || positionAccessor->second < 0 ||
      static_cast<std::size_t>(positionAccessor->second) >= model.accessors.size()) {
    error = "primitive has no valid POSITION accessor";
    return false;
  }
  const tinygltf::Accessor& accessor = model.accessors[std::size_t(positionAccessor->second)];
  if (mesh.num_points() != accessor.count) {
    error = std::string(kExtension) + " decodes " + std::to_string(mesh.num_points()) +
            " points, the POSITION accessor says " + std::to_string(accessor.count);
    return false;
  }
  if (!readAttribute(mesh, *attributes, "POSITION", positions, error)) return false;
  for (const glm::vec3& p : positions) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      error = std::string(kExtension) + " POSITION contains a non-finite value";
      return false;
    }
  }
  if (!insideBounds(accessor, positions)) {
    error = std::string(kExtension) + " POSITION values lie outside the accessor's min/max";
    return false;
  }
  normals.clear();
  if (member(*attributes, "NORMAL") != nullptr &&
      !readAttribute(mesh, *attributes, "NORMAL", normals, error)) {
    return false;
  }
  indices.clear();
  indices.reserve(std::size_t(mesh.num_faces()) * 3);
  for (draco::FaceIndex f(0); f < mesh.num_faces(); ++f) {
    for (const draco::PointIndex& p : mesh.face(f)) {
      if (p.value() >= mesh.num_points()) {
        error = std::string(kExtension) + " face " + std::to_string(f.value()) +
                " refers to a missing point";
        return false;
      }
      indices.push_back(p.value());
    }
  }
  return true;
}

}  // namespace ocean_scene::gltf
