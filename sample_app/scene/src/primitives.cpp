#include <array>
#include <cmath>
#include <map>
#include <utility>

#include "scene/mesh_builders.h"

namespace ocean_scene {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

// Midpoint vertices are shared between the two triangles of an edge, so the sphere stays
// watertight and the rock displacement cannot crack it.
std::uint32_t midpoint(Mesh& mesh,
                       std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t>& cache,
                       std::uint32_t a, std::uint32_t b) {
  const auto key = a < b ? std::make_pair(a, b) : std::make_pair(b, a);
  const auto it = cache.find(key);
  if (it != cache.end()) return it->second;
  const glm::vec3 p = glm::normalize(mesh.positions[a] + mesh.positions[b]);
  const auto index = static_cast<std::uint32_t>(mesh.positions.size());
  mesh.positions.push_back(p);
  cache.emplace(key, index);
  return index;
}

}  // namespace

Mesh makeIcosphere(int subdivisions, const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  const float t = (1.0f + std::sqrt(5.0f)) * 0.5f;
  const std::array<glm::vec3, 12> corners = {
      glm::vec3(-1, t, 0), glm::vec3(1, t, 0), glm::vec3(-1, -t, 0), glm::vec3(1, -t, 0),
      glm::vec3(0, -1, t), glm::vec3(0, 1, t), glm::vec3(0, -1, -t), glm::vec3(0, 1, -t),
      glm::vec3(t, 0, -1), glm::vec3(t, 0, 1), glm::vec3(-t, 0, -1), glm::vec3(-t, 0, 1)};
  for (const glm::vec3& c : corners) mesh.positions.push_back(glm::normalize(c));
  mesh.indices = {0, 11, 5,  0, 5,  1, 0, 1, 7, 0, 7,  10, 0, 10, 11, 1, 5, 9, 5, 11,
                  4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3,  9,  4, 3,  4,  2, 3, 2, 6, 3,
                  6, 8,  3,  8, 9,  4, 9, 5, 2, 4, 11, 6,  2, 10, 8,  6, 7, 9, 8, 1};
  const int levels = subdivisions < 0 ? 0 : (subdivisions > 7 ? 7 : subdivisions);
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> cache;
    std::vector<std::uint32_t> next;
    next.reserve(mesh.indices.size() * 4);
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
      const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
      const std::uint32_t ab = midpoint(mesh, cache, a, b);
      const std::uint32_t bc = midpoint(mesh, cache, b, c);
      const std::uint32_t ca = midpoint(mesh, cache, c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    mesh.indices = std::move(next);
  }
  mesh.normals = mesh.positions;
  return mesh;
}

Mesh makeBox(const glm::vec3& halfExtent, const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  struct Face {
    glm::vec3 n, u, v;  // u x v = n, which makes the quad counter-clockwise from outside
  };
  const std::array<Face, 6> faces = {
      Face{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, Face{{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      Face{{0, 1, 0}, {0, 0, 1}, {1, 0, 0}}, Face{{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
      Face{{0, 0, 1}, {1, 0, 0}, {0, 1, 0}}, Face{{0, 0, -1}, {0, 1, 0}, {1, 0, 0}}};
  for (const Face& f : faces) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    const std::array<glm::vec2, 4> corners = {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1),
                                              glm::vec2(-1, 1)};
    for (const glm::vec2& c : corners) {
      mesh.positions.push_back((f.n + c.x * f.u + c.y * f.v) * halfExtent);
      mesh.normals.push_back(f.n);
    }
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return mesh;
}

Mesh makeCylinder(float radius, float y0, float y1, int segments, const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  const auto n = static_cast<std::uint32_t>(segments < 3 ? 3 : segments);
  auto ring = [&](float y, bool sideNormals, float capNormalY) {
    for (std::uint32_t i = 0; i < n; ++i) {
      const float a = kTwoPi * static_cast<float>(i) / static_cast<float>(n);
      const glm::vec3 dir(std::cos(a), 0.0f, std::sin(a));
      mesh.positions.push_back(glm::vec3(radius * dir.x, y, radius * dir.z));
      mesh.normals.push_back(sideNormals ? dir : glm::vec3(0.0f, capNormalY, 0.0f));
    }
  };
  ring(y0, true, 0.0f);
  ring(y1, true, 0.0f);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.indices.insert(mesh.indices.end(), {i, n + i, j, j, n + i, n + j});
  }
  for (int cap = 0; cap < 2; ++cap) {
    const float y = cap == 0 ? y0 : y1;
    const float ny = cap == 0 ? -1.0f : 1.0f;
    const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.push_back(glm::vec3(0.0f, y, 0.0f));
    mesh.normals.push_back(glm::vec3(0.0f, ny, 0.0f));
    const std::uint32_t first = centre + 1;
    ring(y, false, ny);
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = first + i, b = first + (i + 1) % n;
      if (cap == 0) {
        mesh.indices.insert(mesh.indices.end(), {centre, a, b});
      } else {
        mesh.indices.insert(mesh.indices.end(), {centre, b, a});
      }
    }
  }
  return mesh;
}

Mesh makeTorus(float majorRadius, float minorRadius, int majorSegments, int minorSegments,
               const std::string& name) {
  Mesh mesh;
  mesh.name = name;
  const auto nu = static_cast<std::uint32_t>(majorSegments < 3 ? 3 : majorSegments);
  const auto nv = static_cast<std::uint32_t>(minorSegments < 3 ? 3 : minorSegments);
  for (std::uint32_t i = 0; i < nu; ++i) {
    const float theta = kTwoPi * static_cast<float>(i) / static_cast<float>(nu);
    for (std::uint32_t j = 0; j < nv; ++j) {
      const float phi = kTwoPi * static_cast<float>(j) / static_cast<float>(nv);
      const glm::vec3 n(std::cos(phi) * std::cos(theta), std::sin(phi),
                        std::cos(phi) * std::sin(theta));
      const glm::vec3 centre(majorRadius * std::cos(theta), 0.0f, majorRadius * std::sin(theta));
      mesh.positions.push_back(centre + minorRadius * n);
      mesh.normals.push_back(n);
    }
  }
  auto at = [&](std::uint32_t i, std::uint32_t j) { return (i % nu) * nv + (j % nv); };
  for (std::uint32_t i = 0; i < nu; ++i) {
    for (std::uint32_t j = 0; j < nv; ++j) {
      mesh.indices.insert(mesh.indices.end(), {at(i, j), at(i, j + 1), at(i + 1, j), at(i + 1, j),
                                               at(i, j + 1), at(i + 1, j + 1)});
    }
  }
  return mesh;
}

}  // namespace ocean_scene
