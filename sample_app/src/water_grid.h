#pragma once
// The water surface's mesh: a polar grid centred on the camera, rings spaced geometrically from
// centimetres (the waterline preset sits 3 cm above the water) to kilometres.
#include <epoxy/gl.h>

#include <glkit/handle.h>

namespace ocean {

class WaterGrid {
 public:
  void create(int rings, int segments, float innerRadius, float outerRadius);
  void draw() const;

 private:
  glkit::VertexArray vao_;
  glkit::Buffer vertices_, indices_;
  GLsizei indexCount_ = 0;
};

}  // namespace ocean
