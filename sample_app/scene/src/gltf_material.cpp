#include "gltf_material.h"

#include <cmath>

#include "gltf_text.h"
#include "gltf_value.h"

namespace ocean_scene::gltf {

namespace {

const tinygltf::Value* extension(const tinygltf::Material& material, const char* name) {
  const auto it = material.extensions.find(name);
  return it == material.extensions.end() ? nullptr : &it->second;
}

// Reads object[key] when present; an absent key leaves `out` alone.
bool readNumber(const tinygltf::Value& object, const char* key, float& out, std::string& error) {
  const tinygltf::Value* value = member(object, key);
  if (value == nullptr) return true;
  if (!value->IsNumber() || !std::isfinite(value->GetNumberAsDouble())) {
    error = std::string(key) + " is not a finite number";
    return false;
  }
  out = static_cast<float>(value->GetNumberAsDouble());
  return true;
}

bool readColor3(const tinygltf::Value& object, const char* key, glm::vec3& out,
                std::string& error) {
  const tinygltf::Value* value = member(object, key);
  if (value == nullptr) return true;
  if (!value->IsArray() || value->ArrayLen() != 3) {
    error = std::string(key) + " is not an array of 3 numbers";
    return false;
  }
  for (int i = 0; i < 3; ++i) {
    const tinygltf::Value& c = value->Get(i);
    if (!c.IsNumber() || !std::isfinite(c.GetNumberAsDouble())) {
      error = std::string(key) + " has a non-finite component";
      return false;
    }
    out[i] = static_cast<float>(c.GetNumberAsDouble());
  }
  return true;
}

bool inUnitRange(float v) {
  return v >= 0.0f && v <= 1.0f;
}

bool fail(const tinygltf::Material& source, const std::string& what, std::string& error) {
  error = "material '" + excerpt(source.name) + "': " + what;
  return false;
}

}  // namespace

bool readMaterial(const tinygltf::Material& source, Material& out, std::string& error) {
  out = Material{};
  out.name = source.name;
  out.doubleSided = source.doubleSided;
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  if (pbr.baseColorFactor.size() == 4) {
    for (int i = 0; i < 4; ++i) {
      const double v = pbr.baseColorFactor[static_cast<std::size_t>(i)];
      if (!std::isfinite(v) || v < 0.0 || v > 1.0) {
        return fail(source, "baseColorFactor outside [0, 1]", error);
      }
    }
    out.baseColor = glm::vec3(
        glm::dvec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]));
    out.alpha = static_cast<float>(pbr.baseColorFactor[3]);
  }
  out.metallic = static_cast<float>(pbr.metallicFactor);
  out.roughness = static_cast<float>(pbr.roughnessFactor);
  if (!inUnitRange(out.metallic) || !inUnitRange(out.roughness)) {
    return fail(source, "metallicFactor or roughnessFactor outside [0, 1]", error);
  }

  std::string what;
  if (const tinygltf::Value* ior = extension(source, "KHR_materials_ior")) {
    if (!readNumber(*ior, "ior", out.ior, what)) return fail(source, what, error);
    // The spec allows [1, inf) and exactly 0 (an infinite IOR: Fresnel 1, a mirror).
    if (out.ior < 1.0f && out.ior != 0.0f) {
      return fail(source, "KHR_materials_ior ior must be 0 or at least 1", error);
    }
  }
  if (const tinygltf::Value* d = extension(source, "KHR_materials_dispersion")) {
    if (!readNumber(*d, "dispersion", out.dispersion, what)) return fail(source, what, error);
    if (out.dispersion < 0.0f) return fail(source, "KHR_materials_dispersion below 0", error);
  }
  if (const tinygltf::Value* t = extension(source, "KHR_materials_transmission")) {
    if (!readNumber(*t, "transmissionFactor", out.transmission, what)) {
      return fail(source, what, error);
    }
    if (!inUnitRange(out.transmission)) {
      return fail(source, "transmissionFactor outside [0, 1]", error);
    }
  }
  if (const tinygltf::Value* v = extension(source, "KHR_materials_volume")) {
    if (!readNumber(*v, "thicknessFactor", out.thickness, what) ||
        !readNumber(*v, "attenuationDistance", out.attenuationDistance, what) ||
        !readColor3(*v, "attenuationColor", out.attenuationColor, what)) {
      return fail(source, what, error);
    }
    if (out.thickness < 0.0f) return fail(source, "thicknessFactor below 0", error);
    if (!(out.attenuationDistance > 0.0f)) {
      return fail(source, "attenuationDistance must be positive", error);
    }
    for (int i = 0; i < 3; ++i) {
      if (!inUnitRange(out.attenuationColor[i])) {
        return fail(source, "attenuationColor outside [0, 1]", error);
      }
    }
  }
  return true;
}

std::string ignoredTextures(const tinygltf::Material& source, bool baseColourUsed) {
  std::string names;
  auto add = [&names](int index, const char* name) {
    if (index < 0) return;
    names += names.empty() ? "" : ", ";
    names += name;
  };
  const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
  if (!baseColourUsed) add(pbr.baseColorTexture.index, "baseColorTexture");
  add(pbr.metallicRoughnessTexture.index, "metallicRoughnessTexture");
  add(source.normalTexture.index, "normalTexture");
  add(source.occlusionTexture.index, "occlusionTexture");
  add(source.emissiveTexture.index, "emissiveTexture");
  // Extension textures: any member whose name ends in "Texture".
  for (const auto& [extensionName, value] : source.extensions) {
    if (!value.IsObject()) continue;
    for (const std::string& key : value.Keys()) {
      if (key.size() > 7 && key.compare(key.size() - 7, 7, "Texture") == 0) {
        add(0, (extensionName + "." + key).c_str());
      }
    }
  }
  return names;
}

}  // namespace ocean_scene::gltf
