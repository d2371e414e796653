#pragma once
// Seabed caustics on sloped receivers: the plugin's two water lookups (the default, along the
// refracted light to where the light entered the water, and Feature::TriplanarWalls, the
// world-axis projections for steep surfaces) against converged CPU light tracing onto the same
// tilted plane (sloped_plane.h), through the same water texture the GPU read.
//
// The sun keeps the host frame's elevation but is turned to the +x azimuth, so that the planes,
// tilted about the world z axis, face it (facing +1) or turn away from it (-1). Both lookups run
// the ray-deviation coefficient at the frame's defaults; omega has no absolute scale, so the error is
// the relative RMSE after the best affine fit (ErrorStats::affineRmse), the metric of the flat
// ray-deviation rows, over bins of binPixels^2 pixels.
#include <cstdint>
#include <string>
#include <vector>

#include <postfx/postfx.h>

#include "error_metrics.h"
#include "pass_runner.h"

namespace ocean::validation {

struct SlopeSettings {
  int width = 160, height = 96;  // of the view; multiples of binPixels
  int binPixels = 8;
  double receiverDepth = 6.5;  // m below the level at the image centre
  double viewDistance = 4.0;   // m from the plane, along its normal
  double referenceError = 0.02;
  std::uint64_t maxRays = 400'000'000;
  int timedFrames = 16;
  bool progress = true;  // stderr
  // The ray-deviation settings both lookups run (surfaceFadeDepth is forced to 0: the reference has
  // no fade).
  postfx::CausticsSettings caustics;
  // > 0: also run the WavefrontAreaRatio model at this grid resolution, with its window over
  // the whole view. Inside its window it uses neither lookup, so it checks the comparison
  // itself (plane, bins, units): a model that follows the traced pattern on flat floors must
  // follow it on the slopes too.
  int physicalGrid = 0;
};

struct SlopeLookup {
  PassRun run;
  std::vector<double> binned;  // raw / (L.y n.y) per bin: the reference's units
  ErrorStats stats;
};

struct SlopeCase {
  double slopeDegrees = 0.0;
  int facing = 1;
  double normalDotLight = 1.0;  // n.L with the refracted flat-water sun
  double flatWater = 1.0;       // the bins' value under flat water, n.L / (L.y n.y)
  std::vector<double> reference, referenceSigma;  // per bin; sigma: stated standard error
  double referenceMedianError = 0.0;
  bool referenceConverged = false;
  std::uint64_t referenceRays = 0;
  // sqrt(sum sigma^2 / sum r^2): the most the reference's noise can move a relative RMSE.
  double referenceNoise = 0.0;
  ErrorStats uniform;  // drawing no pattern (constant light)
  SlopeLookup alongLight, triplanar;
  SlopeLookup physical;  // run when SlopeSettings::physicalGrid > 0
  // Standard deviation, from the reference's noise, of triplanar's affine error minus
  // alongLight's (affineRmseDifferenceNoise).
  double differenceNoise = 0.0;
};

// One slope angle, one case per entry of `facings` (one reference trace serves them all: their
// bins coincide).
bool measureSlope(const postfx::FrameDesc& hostFrame, const SlopeSettings& settings,
                  double slopeDegrees, const std::vector<int>& facings,
                  std::vector<SlopeCase>& cases, std::string& error);

}  // namespace ocean::validation
