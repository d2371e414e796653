#include "gltf_spec_rules.h"

#include <cstdint>

#include <nlohmann/json.hpp>

#include "gltf_text.h"

namespace ocean_scene::gltf {

namespace {

using Json = nlohmann::json;

std::string at(const char* array, std::size_t i) {
  return std::string(array) + "[" + std::to_string(i) + "]";
}

bool assetVersion(const Json& root, std::string& error) {
  const std::string fix =
      "; this loader reads glTF 2.0, whose asset.version is \"2.0\" (\"2.x\" for later minor "
      "versions): convert the file to glTF 2.0";
  const auto asset = root.find("asset");
  if (asset == root.end() || !asset->is_object() || !asset->contains("version")) {
    error = "asset.version is missing" + fix;
    return false;
  }
  const Json& version = (*asset)["version"];
  if (!version.is_string()) {
    error = "asset.version is " + excerpt(version.dump()) + ", not a string" + fix;
    return false;
  }
  const std::string text = version.get<std::string>();
  if (text.size() >= 3 && text[0] == '2' && text[1] == '.' && text[2] >= '0' && text[2] <= '9') {
    return true;
  }
  error = "asset.version is \"" + excerpt(text) + "\"" + fix;
  return false;
}

bool byteStrides(const Json& root, std::string& error) {
  const auto views = root.find("bufferViews");
  if (views == root.end() || !views->is_array()) return true;
  for (std::size_t i = 0; i < views->size(); ++i) {
    const Json& view = (*views)[i];
    if (!view.is_object() || !view.contains("byteStride")) continue;
    const Json& stride = view["byteStride"];
    // Not a non-negative integer: the preflight's integer check refuses it first.
    if (!stride.is_number_unsigned()) continue;
    const std::uint64_t s = stride.get<std::uint64_t>();
    if (s >= 4 && s <= 252 && s % 4 == 0) continue;
    error = at("bufferViews", i) + ".byteStride is " + std::to_string(s) +
            "; when present it must be a multiple of 4 from 4 to 252: leave it out for tightly "
            "packed elements";
    return false;
  }
  return true;
}

bool baseColorFactors(const Json& root, std::string& error) {
  const auto materials = root.find("materials");
  if (materials == root.end() || !materials->is_array()) return true;
  for (std::size_t i = 0; i < materials->size(); ++i) {
    const Json& material = (*materials)[i];
    if (!material.is_object()) continue;
    const auto pbr = material.find("pbrMetallicRoughness");
    if (pbr == material.end() || !pbr->is_object()) continue;
    const auto factor = pbr->find("baseColorFactor");
    if (factor == pbr->end()) continue;
    bool numbers = factor->is_array() && factor->size() == 4;
    for (std::size_t c = 0; numbers && c < 4; ++c) numbers = (*factor)[c].is_number();
    if (numbers) continue;
    const std::string written =
        factor->is_array() ? std::to_string(factor->size()) + " value(s)" : excerpt(factor->dump());
    error = at("materials", i) + ".pbrMetallicRoughness.baseColorFactor is " + written +
            "; it must be 4 numbers (red, green, blue, alpha, each in [0, 1]): [1, 1, 1, 1] is "
            "the default, or leave it out";
    return false;
  }
  return true;
}

bool hasExtension(const Json& object, const char* name) {
  const auto extensions = object.find("extensions");
  return extensions != object.end() && extensions->is_object() && extensions->contains(name);
}

bool indexData(const Json& root, std::string& error) {
  const auto meshes = root.find("meshes");
  const auto accessors = root.find("accessors");
  if (meshes == root.end() || !meshes->is_array() || accessors == root.end() ||
      !accessors->is_array()) {
    return true;
  }
  for (std::size_t m = 0; m < meshes->size(); ++m) {
    const Json& mesh = (*meshes)[m];
    const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
    if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
    for (std::size_t p = 0; p < primitives->size(); ++p) {
      const Json& primitive = (*primitives)[p];
      if (!primitive.is_object() || hasExtension(primitive, "KHR_draco_mesh_compression")) {
        continue;
      }
      const auto indices = primitive.find("indices");
      if (indices == primitive.end() || !indices->is_number_unsigned()) continue;
      const std::uint64_t a = indices->get<std::uint64_t>();
      if (a >= accessors->size()) continue;  // the accessor checks name a missing one
      const Json& accessor = (*accessors)[std::size_t(a)];
      if (!accessor.is_object() || accessor.contains("bufferView")) continue;
      error = at("meshes", m) + ".primitives[" + std::to_string(p) + "].indices is accessors[" +
              std::to_string(a) +
              "], which has no bufferView (its values would all be 0): an index accessor "
              "needs its data in a bufferView";
      return false;
    }
  }
  return true;
}

}  // namespace

bool followsSpecRules(const Json& root, std::string& error) {
  return assetVersion(root, error) && byteStrides(root, error) && baseColorFactors(root, error) &&
         indexData(root, error);
}

}  // namespace ocean_scene::gltf
