#pragma once
// The water surface's meshes: the sea's polar grid centred on the camera, rings spaced
// geometrically from centimetres (the waterline preset sits 3 cm above the water) to kilometres;
// or a local water region's square, [-0.5, 0.5]^2 of its local u, v in `cells` x `cells` quads.
#include <epoxy/gl.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

#include <glkit/handle.h>

namespace ocean {

class WaterGrid {
 public:
  void create(int rings, int segments, float innerRadius, float outerRadius);
  void createSquare(int cells);
  void draw() const;
  bool empty() const { return indexCount_ == 0; }

 private:
  void upload(const std::vector<glm::vec2>& points, const std::vector<uint32_t>& indices);

  glkit::VertexArray vao_;
  glkit::Buffer vertices_, indices_;
  GLsizei indexCount_ = 0;
};

}  // namespace ocean
