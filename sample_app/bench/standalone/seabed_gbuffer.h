#pragma once
// The standalone bench's scene: a dune seabed 4-9 m under the water seen from 2 m below the
// surface, looking 20 degrees down, sky (nothing drawn) above the horizon, as a G-buffer from the
// synthetic G-buffer builder (uploaded once). Depth forward [0,1] (depth convention 1), normals
// world xyz RGBA16F (normal encoding 1), albedo RGBA8 sand, target RGBA16F.
#include <glm/glm.hpp>

#include <synthetic_gbuffer.h>

namespace postfx::bench {

struct SeabedView {
  glm::dvec3 eye{0.0, -2.0, 0.0};
  glm::dmat4 view{1.0};        // rotation only
  glm::dmat4 projection{1.0};  // forward [0,1] depth
};

class SeabedGbuffer {
 public:
  SeabedGbuffer(int width, int height);

  GLuint depth() const { return gbuffer_.depth(); }
  GLuint normal() const { return gbuffer_.normal(); }
  GLuint albedo() const { return gbuffer_.albedo(); }
  GLuint target() const { return gbuffer_.target(); }
  const SeabedView& view() const { return view_; }
  double seabedFraction() const { return gbuffer_.coverage(); }  // pixels that show the seabed

 private:
  SeabedView view_;
  ocean::validation::SyntheticGbuffer gbuffer_;
};

}  // namespace postfx::bench
