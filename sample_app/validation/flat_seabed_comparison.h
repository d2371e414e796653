#pragma once
// The flat seabed comparison: a flat seabed seen straight from above (one plane G-buffer), its
// converged CPU light tracing (ocean::reference::traceSeabedCaustics) through the water texture
// the GPU reads, and the plugin's raw caustic factor, divided by N.L, averaged over the same bins
// (blocks of whole pixels). On a flat seabed the light relative to flat water's is the pattern
// itself (flat water = 1). Used by the plugin's tests and the report's caustics rows.
#include <memory>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <postfx/testing.h>
#include <seabed_reference.h>

#include "pass_runner.h"

namespace ocean::validation {

struct FlatSeabedSettings {
  // Of the comparison view; multiples of binPixels. The view's field is fixed (60 degrees
  // vertical), so a larger view compares the pattern on finer bins: what a user's resolution shows.
  int width = 192, height = 108;
  int binPixels = 4;             // pixels per reference bin side
  double cameraDepth = 1.0;      // m below the level
  double receiverDepth = 6.5;    // m below the level (between the physical model's layers)
  double referenceError = 0.01;  // target median relative error per bin
};

class PlaneGbuffer;

class FlatSeabedComparison {
 public:
  FlatSeabedComparison();
  ~FlatSeabedComparison();
  FlatSeabedComparison(const FlatSeabedComparison&) = delete;
  FlatSeabedComparison& operator=(const FlatSeabedComparison&) = delete;

  // Traces the reference through `hostFrame`'s water texture (its sun, optics, water).
  bool prepare(const postfx::FrameDesc& hostFrame, const FlatSeabedSettings& settings,
               std::string& error);
  // One caustics configuration on the seabed (postfx::testing::RawCausticOutput is added): its run,
  // and its raw factor / N.L averaged over each reference bin.
  bool run(postfx::CreateDesc create, const postfx::CausticsSettings& caustics, int timedFrames,
           PassRun& out, std::vector<double>& binned, std::string& error) const;

  const std::vector<double>& truth() const { return reference_.receivers[0].irradiance; }
  const ocean::reference::ReferenceResult& reference() const { return reference_; }
  const ocean::reference::ReferenceDesc& desc() const { return desc_; }
  // streakRatio (streak_ratio.h) of values on the reference's bins.
  double streakRatio(const std::vector<double>& binned) const;

 private:
  std::vector<double> binRaw(const std::vector<float>& raw) const;

  FlatSeabedSettings settings_;
  postfx::FrameDesc frame_;
  std::unique_ptr<PlaneGbuffer> gbuffer_;
  std::unique_ptr<ReportTarget> target_;
  ocean::reference::ReferenceDesc desc_;
  ocean::reference::ReferenceResult reference_;
  double cosine_ = 1.0;  // N.L of the floor: the refracted sun's cosine to the vertical
};

// std / mean of `values`: a pattern's contrast (NaN when the mean is not positive).
double contrast(const std::vector<double>& values);

}  // namespace ocean::validation
