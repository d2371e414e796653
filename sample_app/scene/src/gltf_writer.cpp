#include "scene/gltf_writer.h"

#include <cmath>
#include <cstring>
#include <exception>

#include <tiny_gltf.h>

namespace ocean_scene {

namespace {

// Appends raw bytes as a new buffer view, padded so the next view stays 4-byte aligned
// (glTF requires accessor offsets aligned to their component size).
int addView(tinygltf::Model& gltf, const void* data, std::size_t bytes, int target) {
  std::vector<unsigned char>& buffer = gltf.buffers[0].data;
  const std::size_t offset = buffer.size();
  buffer.resize(offset + bytes);
  std::memcpy(buffer.data() + offset, data, bytes);
  while (buffer.size() % 4 != 0) buffer.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = bytes;
  view.target = target;
  gltf.bufferViews.push_back(view);
  return static_cast<int>(gltf.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& gltf, int view, int componentType, int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  gltf.accessors.push_back(accessor);
  return static_cast<int>(gltf.accessors.size() - 1);
}

int addVec3(tinygltf::Model& gltf, const std::vector<glm::vec3>& values, bool withBounds) {
  const int view =
      addView(gltf, values.data(), values.size() * sizeof(glm::vec3), TINYGLTF_TARGET_ARRAY_BUFFER);
  const int index =
      addAccessor(gltf, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, values.size());
  if (withBounds && !values.empty()) {  // POSITION must carry min/max
    glm::vec3 lo = values[0], hi = values[0];
    for (const glm::vec3& v : values) {
      lo = glm::min(lo, v);
      hi = glm::max(hi, v);
    }
    tinygltf::Accessor& accessor = gltf.accessors[static_cast<std::size_t>(index)];
    accessor.minValues = {lo.x, lo.y, lo.z};
    accessor.maxValues = {hi.x, hi.y, hi.z};
  }
  return index;
}

int addIndices(tinygltf::Model& gltf, const Mesh& mesh) {
  if (mesh.positions.size() <= 0xffffU) {
    std::vector<std::uint16_t> narrow(mesh.indices.begin(), mesh.indices.end());
    const int view = addView(gltf, narrow.data(), narrow.size() * sizeof(std::uint16_t),
                             TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    return addAccessor(gltf, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                       narrow.size());
  }
  const int view = addView(gltf, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t),
                           TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  return addAccessor(gltf, view, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                     mesh.indices.size());
}

tinygltf::Value object(tinygltf::Value::Object members) {
  return tinygltf::Value(std::move(members));
}

tinygltf::Value number(float v) {
  return tinygltf::Value(static_cast<double>(v));
}

void addExtensionUsed(tinygltf::Model& gltf, const std::string& name) {
  for (const std::string& used : gltf.extensionsUsed) {
    if (used == name) return;
  }
  gltf.extensionsUsed.push_back(name);
}

tinygltf::Material toGltf(tinygltf::Model& gltf, const Material& m) {
  tinygltf::Material out;
  out.name = m.name;
  out.doubleSided = m.doubleSided;
  out.pbrMetallicRoughness.baseColorFactor = {m.baseColor.r, m.baseColor.g, m.baseColor.b, m.alpha};
  out.pbrMetallicRoughness.metallicFactor = m.metallic;
  out.pbrMetallicRoughness.roughnessFactor = m.roughness;
  // IOR is written for refractive materials even at its default so readers see it stated.
  if (m.isRefractive() || m.ior != 1.5f) {
    out.extensions["KHR_materials_ior"] = object({{"ior", number(m.ior)}});
    addExtensionUsed(gltf, "KHR_materials_ior");
  }
  if (m.transmission > 0.0f) {
    out.extensions["KHR_materials_transmission"] =
        object({{"transmissionFactor", number(m.transmission)}});
    addExtensionUsed(gltf, "KHR_materials_transmission");
  }
  if (m.dispersion > 0.0f) {
    out.extensions["KHR_materials_dispersion"] = object({{"dispersion", number(m.dispersion)}});
    addExtensionUsed(gltf, "KHR_materials_dispersion");
  }
  const bool hasAttenuation = std::isfinite(m.attenuationDistance);
  if (m.thickness > 0.0f || hasAttenuation) {
    tinygltf::Value::Object volume;
    volume["thicknessFactor"] = number(m.thickness);
    // JSON has no infinity: an absent attenuationDistance means "no absorption".
    if (hasAttenuation) volume["attenuationDistance"] = number(m.attenuationDistance);
    volume["attenuationColor"] = tinygltf::Value(tinygltf::Value::Array{
        number(m.attenuationColor.r), number(m.attenuationColor.g), number(m.attenuationColor.b)});
    out.extensions["KHR_materials_volume"] = object(std::move(volume));
    addExtensionUsed(gltf, "KHR_materials_volume");
  }
  return out;
}

bool isIdentity(const glm::mat4& m) {
  return m == glm::mat4(1.0f);
}

bool validate(const Model& model, std::string& error) {
  for (const Mesh& mesh : model.meshes) {
    if (mesh.positions.empty() || mesh.indices.empty() || mesh.indices.size() % 3 != 0) {
      error = "mesh '" + mesh.name + "' is empty or not a triangle list";
      return false;
    }
    if (mesh.normals.size() != mesh.positions.size()) {
      error = "mesh '" + mesh.name + "' has a normal count different from its position count";
      return false;
    }
    if (mesh.material >= model.materials.size()) {
      error = "mesh '" + mesh.name + "' refers to missing material";
      return false;
    }
    for (std::uint32_t index : mesh.indices) {
      if (index >= mesh.positions.size()) {
        error = "mesh '" + mesh.name + "' has an index out of range";
        return false;
      }
    }
  }
  for (const Instance& instance : model.instances) {
    if (instance.mesh >= model.meshes.size()) {
      error = "instance '" + instance.name + "' refers to missing mesh";
      return false;
    }
  }
  return true;
}

tinygltf::Model toGltf(const Model& model) {
  tinygltf::Model gltf;
  gltf.asset.version = "2.0";
  gltf.asset.generator = "ocean_scene writeGlb";
  gltf.buffers.resize(1);
  for (const Material& material : model.materials) gltf.materials.push_back(toGltf(gltf, material));
  for (const Mesh& mesh : model.meshes) {
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    primitive.material = static_cast<int>(mesh.material);
    primitive.attributes["POSITION"] = addVec3(gltf, mesh.positions, true);
    primitive.attributes["NORMAL"] = addVec3(gltf, mesh.normals, false);
    primitive.indices = addIndices(gltf, mesh);
    tinygltf::Mesh out;
    out.name = mesh.name;
    out.primitives.push_back(primitive);
    gltf.meshes.push_back(out);
  }
  tinygltf::Scene scene;
  for (const Instance& instance : model.instances) {
    tinygltf::Node node;
    node.name = instance.name;
    node.mesh = static_cast<int>(instance.mesh);
    if (!isIdentity(instance.transform)) {
      const float* m = &instance.transform[0][0];
      node.matrix.assign(m, m + 16);
    }
    scene.nodes.push_back(static_cast<int>(gltf.nodes.size()));
    gltf.nodes.push_back(node);
  }
  gltf.scenes.push_back(scene);
  gltf.defaultScene = 0;
  return gltf;
}

}  // namespace

bool writeGlb(const Model& model, const std::string& path, std::string& error) {
  try {
    if (!validate(model, error)) {
      error = path + ": " + error;
      return false;
    }
    const tinygltf::Model gltf = toGltf(model);
    tinygltf::TinyGLTF writer;
    if (!writer.WriteGltfSceneToFile(&gltf, path, true, true, false, true)) {
      error = path + ": tinygltf could not write the file";
      return false;
    }
    return true;
  } catch (const std::exception& e) {
    error = path + ": unexpected failure: " + e.what();
  } catch (...) {
    error = path + ": unexpected failure";
  }
  return false;
}

}  // namespace ocean_scene
