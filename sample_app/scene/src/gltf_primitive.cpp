#include "gltf_primitive.h"

#include <cmath>
#include <numeric>

#include "gltf_accessor.h"
#include "scene/mesh_builders.h"

namespace ocean_scene::gltf {

namespace {

int attribute(const tinygltf::Primitive& primitive, const char* name) {
  const auto it = primitive.attributes.find(name);
  return it == primitive.attributes.end() ? -1 : it->second;
}

bool allFinite(const std::vector<glm::vec3>& values) {
  for (const glm::vec3& v : values) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  }
  return true;
}

// Normalises in place; false if any normal cannot be made unit length.
bool normaliseAll(std::vector<glm::vec3>& normals) {
  for (glm::vec3& n : normals) {
    const float len = glm::length(n);
    if (!std::isfinite(len) || len < 1e-6f) return false;
    n /= len;
  }
  return true;
}

}  // namespace

bool readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, Mesh& out,
                   std::string& error, std::string& notes) {
  // tinygltf stores an absent mode as -1; the glTF default is triangles.
  if (primitive.mode != -1 && primitive.mode != TINYGLTF_MODE_TRIANGLES) {
    error = "primitive mode " + std::to_string(primitive.mode) +
            " is not supported (only TRIANGLES, mode 4)";
    return false;
  }
  const int positionAccessor = attribute(primitive, "POSITION");
  if (positionAccessor < 0) {
    error = "primitive has no POSITION attribute";
    return false;
  }
  if (!readVec3(model, positionAccessor, "POSITION", out.positions, error)) return false;
  if (!allFinite(out.positions)) {
    error =
        "accessor " + std::to_string(positionAccessor) + " (POSITION) contains a non-finite value";
    return false;
  }
  const std::size_t vertexCount = out.positions.size();

  if (primitive.indices >= 0) {
    if (!readIndices(model, primitive.indices, out.indices, error)) return false;
    for (std::size_t i = 0; i < out.indices.size(); ++i) {
      if (out.indices[i] >= vertexCount) {
        error = "index " + std::to_string(out.indices[i]) + " at position " + std::to_string(i) +
                " is out of range for " + std::to_string(vertexCount) + " vertices";
        return false;
      }
    }
  } else {
    if (vertexCount > 0xffffffffULL) {
      error = "too many vertices for 32-bit indices";
      return false;
    }
    out.indices.resize(vertexCount);
    std::iota(out.indices.begin(), out.indices.end(), 0U);
  }
  if (out.indices.size() % 3 != 0) {
    error =
        "triangle list has " + std::to_string(out.indices.size()) + " indices, not a multiple of 3";
    return false;
  }

  const int normalAccessor = attribute(primitive, "NORMAL");
  bool regenerate = normalAccessor < 0;
  if (normalAccessor >= 0) {
    if (!readVec3(model, normalAccessor, "NORMAL", out.normals, error)) return false;
    if (out.normals.size() != vertexCount) {
      error = "NORMAL count " + std::to_string(out.normals.size()) +
              " differs from POSITION count " + std::to_string(vertexCount);
      return false;
    }
    if (!normaliseAll(out.normals)) {
      regenerate = true;
      notes += "mesh '" + out.name + "': zero or non-finite normals regenerated; ";
    }
  }
  if (regenerate) computeSmoothNormals(out);
  return true;
}

}  // namespace ocean_scene::gltf
