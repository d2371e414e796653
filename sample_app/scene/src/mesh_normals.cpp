#include <cmath>

#include "scene/mesh_builders.h"

namespace ocean_scene {

void computeSmoothNormals(Mesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
    if (i0 >= sum.size() || i1 >= sum.size() || i2 >= sum.size()) continue;
    const glm::dvec3 p0(mesh.positions[i0]), p1(mesh.positions[i1]), p2(mesh.positions[i2]);
    // The cross product's length is twice the area, so larger triangles weigh more.
    const glm::dvec3 n = glm::cross(p1 - p0, p2 - p0);
    sum[i0] += n;
    sum[i1] += n;
    sum[i2] += n;
  }
  mesh.normals.resize(mesh.positions.size());
  for (std::size_t i = 0; i < sum.size(); ++i) {
    const double len = glm::length(sum[i]);
    mesh.normals[i] =
        (len > 1e-30 && std::isfinite(len)) ? glm::vec3(sum[i] / len) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

void transformMesh(Mesh& mesh, const glm::mat4& transform) {
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  for (glm::vec3& p : mesh.positions) p = glm::vec3(transform * glm::vec4(p, 1.0f));
  for (glm::vec3& n : mesh.normals) {
    const glm::vec3 m = normalMatrix * n;
    const float len = glm::length(m);
    n = len > 0.0f ? m / len : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  // A mirroring transform turns counter-clockwise triangles clockwise; swap to keep winding.
  if (glm::determinant(glm::mat3(transform)) < 0.0f) {
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      std::swap(mesh.indices[t + 1], mesh.indices[t + 2]);
    }
  }
}

bool normalsAreUnit(const Mesh& mesh, float tolerance) {
  for (const glm::vec3& n : mesh.normals) {
    const float len = glm::length(n);
    if (!std::isfinite(len) || std::abs(len - 1.0f) > tolerance) return false;
  }
  return true;
}

}  // namespace ocean_scene
