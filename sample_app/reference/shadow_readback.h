#pragma once
// The sun shadow map a frame handed the plugin, read back from GL once and sampled on the CPU as
// the plugin's shadow sampler does: bilinear depth comparison (PCF), GL_CLAMP_TO_EDGE.
#include <epoxy/gl.h>

#include <vector>

#include <glm/glm.hpp>

namespace ocean::reference {

// A depth texture (the sun shadow map), level 0.
class ShadowDepth {
 public:
  static ShadowDepth readBack(GLuint texture);
  bool empty() const { return texels_.empty(); }
  // texture(sampler2DShadow, vec3(uv, ref)) with GL_LINEAR: the four nearest texels compared
  // (`reverseZ`: lit where ref >= texel, GL_GEQUAL; else ref <= texel, GL_LEQUAL) and blended
  // with bilinear weights, coordinates clamped to the edge.
  double visibility(glm::dvec2 uv, double ref, bool reverseZ) const;

 private:
  int width_ = 0, height_ = 0;
  std::vector<float> texels_;
};

}  // namespace ocean::reference
