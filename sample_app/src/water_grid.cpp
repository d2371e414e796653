#include "water_grid.h"

#include <glm/glm.hpp>

#include <cmath>
#include <vector>

#include <glkit/handle.h>

namespace ocean {

void WaterGrid::create(int rings, int segments, float innerRadius, float outerRadius) {
  std::vector<glm::vec2> points{glm::vec2(0.0f)};
  const double ratio = std::pow(double(outerRadius) / double(innerRadius), 1.0 / (rings - 1));
  for (int ring = 0; ring < rings; ++ring) {
    const double radius = double(innerRadius) * std::pow(ratio, ring);
    for (int s = 0; s < segments; ++s) {
      const double angle = 2.0 * M_PI * s / segments;
      points.emplace_back(float(radius * std::cos(angle)), float(radius * std::sin(angle)));
    }
  }
  // Counter-clockwise seen from above (+y), so gl_FrontFacing means "seen from above".
  std::vector<uint32_t> indices;
  auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
    const glm::vec2 ab = points[b] - points[a], ac = points[c] - points[a];
    const bool fromAbove = ab.y * ac.x - ab.x * ac.y > 0.0f;  // y of (ab x ac) in xz
    indices.insert(indices.end(), {a, fromAbove ? b : c, fromAbove ? c : b});
  };
  auto at = [segments](int ring, int s) { return uint32_t(1 + ring * segments + s % segments); };
  for (int s = 0; s < segments; ++s) triangle(0, at(0, s), at(0, s + 1));
  for (int ring = 0; ring + 1 < rings; ++ring) {
    for (int s = 0; s < segments; ++s) {
      triangle(at(ring, s), at(ring + 1, s), at(ring + 1, s + 1));
      triangle(at(ring, s), at(ring + 1, s + 1), at(ring, s + 1));
    }
  }
  upload(points, indices);
}

void WaterGrid::createSquare(int cells) {
  std::vector<glm::vec2> points;
  const int n = cells + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      points.emplace_back(float(i) / float(cells) - 0.5f, float(j) / float(cells) - 0.5f);
  // (i, j) -> (i + 1, j) is +u, (i, j) -> (i, j + 1) is +v (+x and +z at rotation 0): (a, c, d)
  // and (a, d, b) are counter-clockwise seen from above, as create()'s triangles.
  std::vector<uint32_t> indices;
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const uint32_t a = uint32_t(j * n + i), b = a + 1, c = a + uint32_t(n), d = c + 1;
      indices.insert(indices.end(), {a, c, d, a, d, b});
    }
  }
  upload(points, indices);
}

void WaterGrid::upload(const std::vector<glm::vec2>& points, const std::vector<uint32_t>& indices) {
  vertices_ =
      glkit::createBuffer(GLsizeiptr(points.size() * sizeof(glm::vec2)), points.data(), 0, {});
  indices_ =
      glkit::createBuffer(GLsizeiptr(indices.size() * sizeof(uint32_t)), indices.data(), 0, {});
  vao_ = glkit::createVertexArray("water.grid");
  const GLuint vao = vao_.id();
  glVertexArrayVertexBuffer(vao, 0, vertices_.id(), 0, sizeof(glm::vec2));
  glVertexArrayElementBuffer(vao, indices_.id());
  glEnableVertexArrayAttrib(vao, 0);
  glVertexArrayAttribFormat(vao, 0, 2, GL_FLOAT, GL_FALSE, 0);
  glVertexArrayAttribBinding(vao, 0, 0);
  indexCount_ = GLsizei(indices.size());
}

void WaterGrid::draw() const {
  glBindVertexArray(vao_.id());
  glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
  glBindVertexArray(0);
}

}  // namespace ocean
