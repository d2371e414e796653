#include "gltf_primitive.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "gltf_accessor.h"
#include "gltf_draco.h"
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

// glTF 2.0 spec 3.7.2.1: strip triangle i is (i, i+1+i%2, i+2-i%2), which keeps the winding;
// fan triangle i is (i+1, i+2, 0).
std::vector<std::uint32_t> toTriangleList(const std::vector<std::uint32_t>& v, bool fan) {
  std::vector<std::uint32_t> list;
  list.reserve((v.size() - 2) * 3);
  for (std::size_t i = 0; i + 2 < v.size(); ++i) {
    if (fan) {
      list.insert(list.end(), {v[i + 1], v[i + 2], v[0]});
    } else {
      list.insert(list.end(), {v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
    }
  }
  return list;
}

}  // namespace

bool readPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive, Mesh& out,
                   std::string& error, std::string& notes) {
  // tinygltf stores an absent mode as -1; the glTF default is triangles.
  const int mode = primitive.mode == -1 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    const char* kind = mode == TINYGLTF_MODE_POINTS       ? "points"
                       : mode == TINYGLTF_MODE_LINE       ? "lines"
                       : mode == TINYGLTF_MODE_LINE_LOOP  ? "a line loop"
                       : mode == TINYGLTF_MODE_LINE_STRIP ? "a line strip"
                                                          : "an unknown mode";
    error = "primitive mode " + std::to_string(mode) + " (" + kind +
            ") is not supported: casters need triangles (modes 4, 5, 6)";
    return false;
  }
  const int positionAccessor = attribute(primitive, "POSITION");
  if (positionAccessor < 0) {
    error = "primitive has no POSITION attribute";
    return false;
  }
  const bool quantization = std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                      "KHR_mesh_quantization") != model.extensionsUsed.end();
  // With Draco the attribute and index accessors have no data of their own: the compressed
  // bufferView holds positions, normals and triangles.
  const bool draco = isDracoPrimitive(primitive);
  std::vector<glm::vec3> dracoNormals;
  if (draco) {
    if (!decodeDracoPrimitive(model, primitive, out.positions, dracoNormals, out.indices, error)) {
      return false;
    }
  } else {
    if (!readVec3(model, positionAccessor, "POSITION", quantization, out.positions, error)) {
      return false;
    }
    if (!allFinite(out.positions)) {
      error = "accessor " + std::to_string(positionAccessor) +
              " (POSITION) contains a non-finite value";
      return false;
    }
  }
  const std::size_t vertexCount = out.positions.size();
  // glTF 2.0 requires POSITION bounds; without them nothing checks the values against the
  // exporter's intent, so the user is told.
  const tinygltf::Accessor& positions = model.accessors[static_cast<std::size_t>(positionAccessor)];
  if (positions.minValues.size() != 3 || positions.maxValues.size() != 3) {
    notes += "mesh '" + out.name + "': POSITION accessor " + std::to_string(positionAccessor) +
             " has no min/max (required by glTF 2.0), values not checked against them; ";
  }

  if (draco || primitive.indices >= 0) {
    if (!draco && !readIndices(model, primitive.indices, out.indices, error)) return false;
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
  // Draco's faces are triangles whatever the primitive's mode says.
  if (mode != TINYGLTF_MODE_TRIANGLES && !draco) {
    if (out.indices.size() < 3) {
      error = "triangle strip or fan has " + std::to_string(out.indices.size()) +
              " vertices, fewer than 3";
      return false;
    }
    out.indices = toTriangleList(out.indices, mode == TINYGLTF_MODE_TRIANGLE_FAN);
  }
  if (out.indices.size() % 3 != 0) {
    error =
        "triangle list has " + std::to_string(out.indices.size()) + " indices, not a multiple of 3";
    return false;
  }

  const int normalAccessor = draco ? -1 : attribute(primitive, "NORMAL");
  bool regenerate = normalAccessor < 0 && dracoNormals.empty();
  if (normalAccessor >= 0 || !dracoNormals.empty()) {
    if (draco) {
      out.normals = std::move(dracoNormals);
    } else if (!readVec3(model, normalAccessor, "NORMAL", quantization, out.normals, error)) {
      return false;
    }
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
