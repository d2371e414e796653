#pragma once
// CPU copies of the GL textures the god-ray pass samples, read back once, and samplers that do
// in double what the plugin's GL samplers do: the water slopes with GL_LINEAR_MIPMAP_LINEAR and
// GL_REPEAT at an explicit level of detail (textureLod), the sun shadow map with bilinear
// depth-comparison (PCF) and GL_CLAMP_TO_EDGE. Needs a current GL context only to read back.
#include <epoxy/gl.h>

#include <vector>

#include <glm/glm.hpp>

namespace reference {

// Slopes (R, G = dh/dx, dh/dz) of every mip level of every cascade layer.
class WaterSlopes {
 public:
  // `texture` is a GL_TEXTURE_2D_ARRAY (layers = cascades) or, with `single2D`, a GL_TEXTURE_2D
  // holding one cascade. Reads every level the texture has (one level: sampled without mips,
  // as the plugin does).
  static WaterSlopes readBack(GLuint texture, int cascades, bool single2D = false);

  int cascades() const { return static_cast<int>(layers_.size()); }
  int levels() const { return layers_.empty() ? 0 : static_cast<int>(layers_[0].size()); }
  int width() const { return levels() ? layers_[0][0].width : 0; }
  int height() const { return levels() ? layers_[0][0].height : 0; }

  // textureLod(sampler2DArray, vec3(uv, cascade), lod).rg with trilinear filtering and repeat.
  glm::dvec2 sample(int cascade, glm::dvec2 uv, double lod) const;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<glm::dvec2> texels;  // row-major, (x, y) at y * width + x
  };
  glm::dvec2 bilinear(const Level& level, glm::dvec2 uv) const;
  std::vector<std::vector<Level>> layers_;  // [cascade][level]
};

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

}  // namespace reference
