#pragma once
// CPU reference of the plugin's god rays: the light model of shaders/postfx/god_rays/godrays.frag
// integrated densely in double precision along every pixel's view ray,
//   L = E * intensity * sigma_s * integral_{t0}^{t1} S(t) exp(-sigma_t (t - t0)) dt,
//   S(t) = rho(depth) * visibility * omega(water normal where the refracted sun entered)
//          * exp(-sigma_t * depth / cos(theta_t)),
// over the underwater part [t0, t1] of the ray, up to the surface the pixel sees or maxDistance.
// The samples are `samples` equal segments of [t0, t1], S taken at each segment's midpoint and
// the exponential integrated exactly over the segment (so any sigma_t is fine). Deterministic
// (no random numbers), multithreaded over pixel rows, progress on stderr.
//
// It reads the same inputs the plugin reads: the depth texture, the water slope texture (every
// mip level) and the sun shadow map, read back from GL once (captureGodRayInputs).
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "shadow_readback.h"
#include "water_readback.h"

namespace ocean::reference {

struct GodRayInputs {
  int width = 0, height = 0;  // of FrameDesc::target
  std::vector<float> depth;   // window depth per pixel, GL order (row 0 at the bottom)
  WaterTextureCopy water;
  ShadowDepth shadow;  // read only with Feature::ShadowMask
};

// Reads back the textures `frame` names (needs the GL context they live in); false with a
// message when the water texture cannot be read.
bool captureGodRayInputs(const postfx::CreateDesc& create, const postfx::FrameDesc& frame,
                         GodRayInputs& inputs, std::string& error);

struct GodRayReferenceOptions {
  int samples = 2048;  // segments per pixel along the underwater part of the ray (>= 1024)
  int threads = 0;     // 0: std::thread::hardware_concurrency()
  bool progress = true;
  // Sample the water texture at the plugin's level of detail (its pixel-footprint mip choice,
  // part of what the plugin computes); false: level 0 only (the unfiltered surface).
  bool footprintLod = true;
};

// The light the god-ray pass adds, linear RGB per pixel in GL order, for the frame the plugin
// would render with `create` / `frame` (zero where the plugin skips the pass). Sample count,
// half resolution and dither settings of frame.godRays are ignored: this is their limit.
// Per pixel, what sets the error of a march with few samples: the transmittance-weighted mean
// and standard deviation of S along the ray (green channel), and the number of world-grid
// planes the plugin's march crosses there ((|d.x'| + |d.z'|) * length / gridSpacing).
struct GodRayPixelStats {
  double sourceMean = 0.0, sourceStd = 0.0, gridCrossings = 0.0;
};

std::vector<glm::dvec3> renderGodRayReference(const postfx::CreateDesc& create,
                                              const postfx::FrameDesc& frame,
                                              const GodRayInputs& inputs,
                                              const GodRayReferenceOptions& options = {},
                                              std::vector<GodRayPixelStats>* stats = nullptr);

// Relative RMSE of `image` (RGBA float, GL order, e.g. a read-back target) against `reference`:
// sqrt(sum |image.rgb - ref|^2 / sum |ref|^2).
double relativeRmse(const std::vector<glm::vec4>& image, const std::vector<glm::dvec3>& reference);
double relativeRmse(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& reference);

}  // namespace ocean::reference
