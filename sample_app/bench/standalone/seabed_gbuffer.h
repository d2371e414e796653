#pragma once
// A G-buffer the standalone bench can make without the sample's renderer: a dune seabed 4-9 m
// under the water seen from 2 m below the surface, looking 20 degrees down, sky (nothing drawn)
// above the horizon. Computed on the CPU by marching each pixel's ray against the height field,
// uploaded once. Depth forward [0,1] (depth convention 1), normals world xyz RGBA16F (normal
// encoding 1), albedo RGBA8 sand, target RGBA16F.
#include <epoxy/gl.h>

#include <glm/glm.hpp>

namespace postfx::bench {

struct SeabedView {
  glm::dvec3 eye{0.0, -2.0, 0.0};
  glm::dmat4 view{1.0};        // rotation only
  glm::dmat4 projection{1.0};  // forward [0,1] depth
};

class SeabedGbuffer {
 public:
  SeabedGbuffer(int width, int height);
  ~SeabedGbuffer();
  SeabedGbuffer(const SeabedGbuffer&) = delete;
  SeabedGbuffer& operator=(const SeabedGbuffer&) = delete;

  GLuint depth() const { return textures_[0]; }
  GLuint normal() const { return textures_[1]; }
  GLuint albedo() const { return textures_[2]; }
  GLuint target() const { return textures_[3]; }
  const SeabedView& view() const { return view_; }
  double seabedFraction() const { return seabedFraction_; }  // pixels that show the seabed

 private:
  GLuint textures_[4] = {};
  SeabedView view_;
  double seabedFraction_ = 0.0;
};

}  // namespace postfx::bench
