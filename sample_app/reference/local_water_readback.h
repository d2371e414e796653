#pragma once
// The frame's local water regions (postfx::LocalWater) read back from GL and laid over the
// cascades' surface: the water the traced reference refracts. Inside region r's rectangle, a
// Replace region is its own surface and an Add region is the surface beneath plus its own;
// outside every rectangle the surface beneath. Each texture is read at level 0, bilinear,
// clamped to its edge, as the plugin's sampler reads it; slopes are turned from the region's
// axes into world x and z. No edge blend: the blend is the plugin's way of joining two light
// fields, not water (an Add region's texture should fade to 0 at its edge, as a wake's absorbing
// band makes it; a Replace region ends where a pool's walls stand).
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <glm/glm.hpp>

#include "seabed_reference.h"

namespace ocean::reference {

class LocalWaterSurface final : public Surface {
 public:
  // Reads every region of `water` (its texture must be a GL texture the plugin accepts) over
  // `beneath`, which must outlive this. False with a message on a bad texture.
  bool read(const postfx::WaterSurface& water, const Surface& beneath, std::string& error);

  SurfaceSample sample(double x, double z) const override;
  double maxHeight() const override { return maxHeight_; }
  double maxSlope() const override { return maxSlope_; }
  double featureSize() const override { return featureSize_; }
  int regionCount() const { return static_cast<int>(regions_.size()); }

 private:
  struct Region {
    glm::dvec2 centre{0.0}, half{0.0}, axisU{1.0, 0.0};
    bool replace = false;
    int width = 0, height = 0;
    std::vector<glm::dvec3> texels;      // (dh/du, dh/dv, h), row-major
    glm::dvec3 at(glm::dvec2 uv) const;  // bilinear, clamped
  };
  const Surface* beneath_ = nullptr;
  std::vector<Region> regions_;
  double maxHeight_ = 0.0, maxSlope_ = 0.0, featureSize_ = 1.0;
};

}  // namespace ocean::reference
