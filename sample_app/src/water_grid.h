#pragma once
// The water surface's mesh: a polar grid centred on the camera, rings spaced geometrically from
// centimetres (the waterline preset sits 3 cm above the water) to kilometres.
#include <epoxy/gl.h>

namespace ocean {

class WaterGrid {
 public:
  WaterGrid() = default;
  WaterGrid(const WaterGrid&) = delete;
  WaterGrid& operator=(const WaterGrid&) = delete;
  ~WaterGrid();
  void create(int rings, int segments, float innerRadius, float outerRadius);
  void draw() const;

 private:
  GLuint vao_ = 0, vertices_ = 0, indices_ = 0;
  GLsizei indexCount_ = 0;
};

}  // namespace ocean
