#include <cmath>

#include "scene/mesh_builders.h"

namespace ocean_scene {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

// Outward normal of a profile segment in the (r, y) plane: the travel direction turned right.
glm::vec2 segmentNormal(const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 d = b - a;
  const float len = glm::length(d);
  return len > 0.0f ? glm::vec2(d.y, -d.x) / len : glm::vec2(0.0f);
}

}  // namespace

Mesh makeLathe(const std::vector<glm::vec2>& profile, int segments, const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  if (profile.size() < 2) return mesh;
  const auto n = static_cast<std::uint32_t>(segments < 3 ? 3 : segments);
  const auto rows = static_cast<std::uint32_t>(profile.size());
  for (std::uint32_t k = 0; k < rows; ++k) {
    glm::vec2 n2(0.0f);
    if (k > 0) n2 += segmentNormal(profile[k - 1], profile[k]);
    if (k + 1 < rows) n2 += segmentNormal(profile[k], profile[k + 1]);
    const float len = glm::length(n2);
    n2 = len > 1e-6f ? n2 / len : glm::vec2(1.0f, 0.0f);
    for (std::uint32_t i = 0; i < n; ++i) {
      const float a = kTwoPi * static_cast<float>(i) / static_cast<float>(n);
      const float c = std::cos(a), s = std::sin(a);
      mesh.positions.push_back(glm::vec3(profile[k].x * c, profile[k].y, profile[k].x * s));
      mesh.normals.push_back(glm::vec3(n2.x * c, n2.y, n2.x * s));
    }
  }
  for (std::uint32_t k = 0; k + 1 < rows; ++k) {
    // A ring on the axis collapses to a point; its half of each quad would be degenerate.
    const bool lowerOnAxis = profile[k].x <= 0.0f;
    const bool upperOnAxis = profile[k + 1].x <= 0.0f;
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t j = (i + 1) % n;
      const std::uint32_t a = k * n + i, b = k * n + j, c = (k + 1) * n + i, d = (k + 1) * n + j;
      if (!lowerOnAxis) mesh.indices.insert(mesh.indices.end(), {a, c, b});
      if (!upperOnAxis) mesh.indices.insert(mesh.indices.end(), {b, c, d});
    }
  }
  return mesh;
}

}  // namespace ocean_scene
