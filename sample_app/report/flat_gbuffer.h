#pragma once
// The report's synthetic receiver: a flat floor seen straight down by a pinhole camera, as a
// G-buffer (every pixel at the same view depth, facing up, white) with the camera matrices that
// make it so. Used where the compared quantity lives on a plane (seabed caustics, the object
// caustics' receiver) and the G-buffer only has to give every pixel that plane.
#include <epoxy/gl.h>

#include <glm/glm.hpp>

namespace ocean::report {

// Looking straight down with image up = world -z (view x = world x, view y = -world z), 60
// degree vertical field of view, reverse-Z with an infinite far plane (depth convention 0).
struct TopDownView {
  glm::dmat4 view{1.0}, projection{1.0};
  float windowDepth = 0.0f;  // of the floor `floorDistance` (m) below the camera
  double focal = 0.0;        // projection[1][1]
  double aspect = 1.0;       // width / height
};
TopDownView topDownView(int width, int height, double floorDistance);

class FlatFloorGbuffer {
 public:
  // Depth GL_DEPTH_COMPONENT32F, normals GL_RGBA16F world xyz (normal encoding 1), albedo RGBA8.
  FlatFloorGbuffer(int width, int height, float windowDepth);
  ~FlatFloorGbuffer();
  FlatFloorGbuffer(const FlatFloorGbuffer&) = delete;
  FlatFloorGbuffer& operator=(const FlatFloorGbuffer&) = delete;
  GLuint depth() const { return textures_[0]; }
  GLuint normal() const { return textures_[1]; }
  GLuint albedo() const { return textures_[2]; }

 private:
  GLuint textures_[3] = {};
};

}  // namespace ocean::report
