#include "scene/gltf_loader.h"

#include <cmath>
#include <cstring>
#include <exception>
#include <fstream>
#include <limits>
#include <vector>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "gltf_material.h"
#include "gltf_primitive.h"

namespace ocean_scene {

namespace {

// tinygltf messages can span lines; callers log one line per failure.
std::string oneLine(std::string text) {
  std::string out;
  for (char c : text) {
    if (c == '\n' || c == '\r') {
      if (!out.empty() && out.back() != ' ') out += "; ";
    } else {
      out += c;
    }
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out;
}

std::string directoryOf(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  return slash == std::string::npos ? std::string(".") : path.substr(0, slash);
}

bool readFile(const std::string& path, std::vector<unsigned char>& bytes, std::string& error) {
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) {
    error = "cannot open file";
    return false;
  }
  const std::streamoff size = file.tellg();
  if (size <= 0) {
    error = size == 0 ? "file is empty" : "cannot read file size";
    return false;
  }
  // tinygltf takes the length as unsigned int.
  if (static_cast<unsigned long long>(size) > std::numeric_limits<unsigned int>::max()) {
    error = "file is larger than 4 GiB";
    return false;
  }
  bytes.resize(static_cast<std::size_t>(size));
  file.seekg(0);
  file.read(reinterpret_cast<char*>(bytes.data()), size);
  if (!file) {
    error = "read failed";
    return false;
  }
  return true;
}

// Textures are ignored by this loader; skipping decode also keeps image parsers off the path.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
  return true;
}

bool parse(const std::string& path, const std::vector<unsigned char>& bytes, tinygltf::Model& model,
           std::string& error, std::string& warnings) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&skipImage, nullptr);
  std::string err, warn;
  const auto size = static_cast<unsigned int>(bytes.size());
  bool ok = false;
  if (bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0) {
    ok = loader.LoadBinaryFromMemory(&model, &err, &warn, bytes.data(), size, directoryOf(path));
  } else if (bytes[0] == '{' || bytes[0] == ' ' || bytes[0] == '\n' || bytes[0] == '\t' ||
             bytes[0] == '\r' || bytes[0] == 0xEF /* UTF-8 BOM */) {
    ok = loader.LoadASCIIFromString(
        &model, &err, &warn, reinterpret_cast<const char*>(bytes.data()), size, directoryOf(path));
  } else {
    error = "not a glTF file (no 'glTF' magic and no JSON object)";
    return false;
  }
  if (!warn.empty()) warnings += oneLine(warn) + "; ";
  if (!ok) {
    error = err.empty() ? "tinygltf could not parse the file" : oneLine(err);
    return false;
  }
  return true;
}

bool nodeLocalTransform(const tinygltf::Node& node, glm::dmat4& out, std::string& error) {
  if (node.matrix.size() == 16) {
    out = glm::make_mat4(node.matrix.data());  // glTF and GLM are both column-major
  } else if (!node.matrix.empty()) {
    error = "node '" + node.name + "' matrix does not have 16 elements";
    return false;
  } else {
    glm::dvec3 t(0.0), s(1.0);
    glm::dquat r(1.0, 0.0, 0.0, 0.0);
    if (node.translation.size() == 3) t = glm::make_vec3(node.translation.data());
    if (node.scale.size() == 3) s = glm::make_vec3(node.scale.data());
    if (node.rotation.size() == 4) {  // glTF order x, y, z, w
      r = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    }
    if ((!node.translation.empty() && node.translation.size() != 3) ||
        (!node.scale.empty() && node.scale.size() != 3) ||
        (!node.rotation.empty() && node.rotation.size() != 4)) {
      error = "node '" + node.name + "' has a malformed translation, rotation or scale";
      return false;
    }
    out = glm::translate(glm::dmat4(1.0), t) * glm::mat4_cast(glm::normalize(r)) *
          glm::scale(glm::dmat4(1.0), s);
  }
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(out[c][r])) {
        error = "node '" + node.name + "' has a non-finite transform";
        return false;
      }
    }
  }
  return true;
}

// meshMap[m] = our mesh indices of glTF mesh m's primitives.
bool flattenNodes(const tinygltf::Model& model,
                  const std::vector<std::vector<std::uint32_t>>& meshMap, Model& out,
                  std::string& error) {
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t>(sceneIndex) >= model.scenes.size()) {
      error = "defaultScene " + std::to_string(sceneIndex) + " does not exist";
      return false;
    }
    roots = model.scenes[static_cast<std::size_t>(sceneIndex)].nodes;
  } else {
    // No scene: every node that is nobody's child is a root.
    std::vector<bool> isChild(model.nodes.size(), false);
    for (const tinygltf::Node& node : model.nodes) {
      for (int child : node.children) {
        if (child >= 0 && static_cast<std::size_t>(child) < isChild.size()) {
          isChild[static_cast<std::size_t>(child)] = true;
        }
      }
    }
    for (std::size_t i = 0; i < model.nodes.size(); ++i) {
      if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
  }
  struct Pending {
    int node;
    glm::dmat4 parent;
  };
  std::vector<Pending> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::dmat4(1.0)});
  // A valid hierarchy is a forest: each node is visited at most once.
  std::vector<bool> visited(model.nodes.size(), false);
  while (!stack.empty()) {
    const Pending item = stack.back();
    stack.pop_back();
    if (item.node < 0 || static_cast<std::size_t>(item.node) >= model.nodes.size()) {
      error = "node " + std::to_string(item.node) + " does not exist";
      return false;
    }
    const auto nodeIndex = static_cast<std::size_t>(item.node);
    if (visited[nodeIndex]) {
      error = "node " + std::to_string(item.node) + " is reached twice (cycle or shared child)";
      return false;
    }
    visited[nodeIndex] = true;
    const tinygltf::Node& node = model.nodes[nodeIndex];
    glm::dmat4 local;
    if (!nodeLocalTransform(node, local, error)) return false;
    const glm::dmat4 world = item.parent * local;
    if (node.mesh >= 0) {
      if (static_cast<std::size_t>(node.mesh) >= meshMap.size()) {
        error = "node '" + node.name + "' refers to missing mesh " + std::to_string(node.mesh);
        return false;
      }
      for (std::uint32_t mesh : meshMap[static_cast<std::size_t>(node.mesh)]) {
        out.instances.push_back(Instance{mesh, glm::mat4(world), node.name});
      }
    }
    for (auto it = node.children.rbegin(); it != node.children.rend(); ++it) {
      stack.push_back({*it, world});
    }
  }
  if (out.instances.empty()) {
    error = "the scene has no node with a mesh";
    return false;
  }
  return true;
}

bool convert(const tinygltf::Model& model, Model& out, std::string& error, std::string& notes) {
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    Material material;
    if (!gltf::readMaterial(model.materials[i], material, error)) return false;
    out.materials.push_back(std::move(material));
  }
  // Primitives without a material get the glTF default material, added once at the end.
  std::uint32_t defaultMaterial = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::vector<std::uint32_t>> meshMap(model.meshes.size());
  for (std::size_t m = 0; m < model.meshes.size(); ++m) {
    const tinygltf::Mesh& source = model.meshes[m];
    for (std::size_t p = 0; p < source.primitives.size(); ++p) {
      const tinygltf::Primitive& primitive = source.primitives[p];
      Mesh mesh;
      mesh.name =
          source.primitives.size() == 1 ? source.name : source.name + "#" + std::to_string(p);
      if (!gltf::readPrimitive(model, primitive, mesh, error, notes)) {
        error = "mesh " + std::to_string(m) + " '" + source.name + "' primitive " +
                std::to_string(p) + ": " + error;
        return false;
      }
      if (primitive.material >= 0) {
        if (static_cast<std::size_t>(primitive.material) >= out.materials.size()) {
          error = "mesh '" + source.name + "' refers to missing material " +
                  std::to_string(primitive.material);
          return false;
        }
        mesh.material = static_cast<std::uint32_t>(primitive.material);
      } else {
        if (defaultMaterial == std::numeric_limits<std::uint32_t>::max()) {
          defaultMaterial = static_cast<std::uint32_t>(out.materials.size());
          Material fallback;
          fallback.name = "gltf_default";
          out.materials.push_back(fallback);
        }
        mesh.material = defaultMaterial;
      }
      meshMap[m].push_back(static_cast<std::uint32_t>(out.meshes.size()));
      out.meshes.push_back(std::move(mesh));
    }
  }
  return flattenNodes(model, meshMap, out, error);
}

}  // namespace

bool loadGlb(const std::string& path, Model& out, std::string& error, std::string* warnings) {
  out = Model{};
  std::string problem, notes;
  bool ok = false;
  try {
    std::vector<unsigned char> bytes;
    tinygltf::Model model;
    ok = readFile(path, bytes, problem) && parse(path, bytes, model, problem, notes) &&
         convert(model, out, problem, notes);
  } catch (const std::exception& e) {
    problem = std::string("unexpected failure: ") + e.what();
    ok = false;
  } catch (...) {
    problem = "unexpected failure";
    ok = false;
  }
  if (!ok) {
    out = Model{};
    error = path + ": " + oneLine(problem);
    return false;
  }
  if (warnings != nullptr) *warnings = oneLine(notes);
  return true;
}

}  // namespace ocean_scene
