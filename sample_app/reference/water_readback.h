#pragma once
// The water texture a frame handed the plugin, read back from GL level 0 into double arrays and
// evaluated on the CPU exactly as postfx::WaterSurface describes it: cascade c covers world xz
// with uv = (xz - origin) / tileSize[c], texel (i, j) centred at uv ((i + 0.5) / N,
// (j + 0.5) / N), bilinear with repeat; the surface is the SUM over cascades of R, G (slopes)
// and B (height). Broken texels are treated as the plugin's shaders treat them: a slope sum that
// is NaN/Inf or beyond 64 becomes 0 (postfx shared sanitizeSlopes), a height sum likewise.
#include <epoxy/gl.h>

#include <string>
#include <vector>

#include <postfx/frame_desc.h>

#include "seabed_reference.h"

namespace ocean::reference {

class WaterTextureSurface final : public Surface {
 public:
  // Reads `water.texture` (GL_TEXTURE_2D_ARRAY or GL_TEXTURE_2D, any of the plugin's accepted
  // formats) level 0. Needs a current GL context; returns false with a message on a bad texture.
  bool read(const postfx::WaterSurface& water, std::string& error);

  SurfaceSample sample(double x, double z) const override;
  double maxHeight() const override { return maxHeight_; }
  double maxSlope() const override { return maxSlope_; }
  double featureSize() const override { return featureSize_; }

  int size() const { return size_; }
  int cascadeCount() const { return cascadeCount_; }

 private:
  struct Texel {
    double slopeX, slopeZ, height;
  };
  int size_ = 0, cascadeCount_ = 0;
  double tileSize_[postfx::kMaxCascades] = {};
  glm::dvec2 origin_{0.0};
  std::vector<Texel> texels_;  // cascade-major, then row (v), then column (u)
  double maxHeight_ = 0.0, maxSlope_ = 0.0, featureSize_ = 1.0;
};

}  // namespace ocean::reference
