#pragma once
// The water texture a frame handed the plugin, read back from GL once into double arrays and
// evaluated on the CPU exactly as postfx::WaterSurface describes it and the plugin's samplers
// read it: cascade c covers world xz with uv = (xz - origin) / tileSize[c], texel (i, j) centred
// at uv ((i + 0.5) / n, (j + 0.5) / n), GL_REPEAT, bilinear within a level and linear between
// levels (GL_LINEAR_MIPMAP_LINEAR at an explicit level of detail, as textureLod).
#include <epoxy/gl.h>

#include <string>
#include <vector>

#include <postfx/frame_desc.h>
#include <glm/glm.hpp>

#include "seabed_reference.h"

namespace ocean::reference {

// Every mip level of every cascade layer: texel = (dh/dx, dh/dz, h), as stored (NaN/Inf kept).
class WaterTextureCopy {
 public:
  // `texture`: GL_TEXTURE_2D_ARRAY (layer c = cascade c) or GL_TEXTURE_2D (one cascade), any
  // format the plugin accepts. Reads every level with storage (one level: sampled without
  // mips, as the plugin does). Needs a current GL context; false with a message on a bad
  // texture.
  bool read(GLuint texture, int cascades, std::string& error);

  int cascades() const { return static_cast<int>(layers_.size()); }
  int levels() const { return layers_.empty() ? 0 : static_cast<int>(layers_[0].size()); }
  int width() const { return levels() ? layers_[0][0].width : 0; }
  int height() const { return levels() ? layers_[0][0].height : 0; }

  const glm::dvec3& texel(int cascade, int level, int i, int j) const {
    const Level& l = layers_[static_cast<size_t>(cascade)][static_cast<size_t>(level)];
    return l.texels[static_cast<size_t>(j) * static_cast<size_t>(l.width) + static_cast<size_t>(i)];
  }
  // One level of one cascade at uv, bilinear with repeat.
  glm::dvec3 bilinear(int cascade, int level, glm::dvec2 uv) const;
  // textureLod(water, vec3(uv, cascade), lod).rgb with trilinear filtering.
  glm::dvec3 sample(int cascade, glm::dvec2 uv, double lod) const;

 private:
  struct Level {
    int width = 0, height = 0;
    std::vector<glm::dvec3> texels;  // row-major, (x, y) at y * width + x
  };
  std::vector<std::vector<Level>> layers_;  // [cascade][level]
};

// The sea the frame describes, level 0 of each cascade summed in world coordinates, as the seabed
// light tracer's Surface. Broken texels are treated as the plugin's shaders treat them: a slope
// sum that is NaN/Inf or beyond 64 becomes 0 (postfx shared sanitizeSlopes), a height sum
// likewise.
class WaterTextureSurface final : public Surface {
 public:
  // Reads `water.texture` (needs a square texture with at least cascadeCount layers).
  bool read(const postfx::WaterSurface& water, std::string& error);

  SurfaceSample sample(double x, double z) const override;
  double maxHeight() const override { return maxHeight_; }
  double maxSlope() const override { return maxSlope_; }
  double featureSize() const override { return featureSize_; }

  int size() const { return water_.width(); }
  int cascadeCount() const { return water_.cascades(); }

 private:
  WaterTextureCopy water_;
  double tileSize_[postfx::kMaxCascades] = {};
  glm::dvec2 origin_{0.0};
  double maxHeight_ = 0.0, maxSlope_ = 0.0, featureSize_ = 1.0;
};

}  // namespace ocean::reference
