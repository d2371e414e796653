#pragma once
// The report's caustics rows: the tile irradiance (the default model) at several tile sizes and
// layer counts, the ray-deviation coefficient at several tau, with and without the reflection
// term, with and without cascade skipping, and the physical (wavefront area ratio) window at
// each grid resolution, each timed and compared with converged CPU light tracing
// (ocean::reference::traceSeabedCaustics) through the same water texture the GPU used.
//
// The comparison scene is a flat seabed seen straight from above, so each bin of the
// reference is a block of whole pixels: the plugin's raw caustic factor, divided by N.L, is
// averaged over the block and compared with the reference irradiance there (flat water = 1).
#include <memory>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <postfx/testing.h>
#include <seabed_reference.h>

#include "pass_runner.h"
#include "report_table.h"

namespace ocean::report {

struct CausticReportSettings {
  int width = 192, height = 108;  // of the comparison view; multiples of binPixels
  int binPixels = 4;              // pixels per reference bin side
  double cameraDepth = 1.0;       // m below the level
  double receiverDepth = 6.5;     // m below the level (between the physical model's layers)
  double referenceError = 0.01;   // target median relative error per bin
  int timedFrames = 16;
  std::vector<int> physicalGrids = {64, 128, 256, 512, 1024};
};

class PlaneGbuffer;

// The comparison: the flat seabed's G-buffer, its converged traced irradiance, and the plugin's
// raw factor binned onto the same bins. Used by the report's rows and by tests.
class FlatSeabedComparison {
 public:
  FlatSeabedComparison();
  ~FlatSeabedComparison();
  FlatSeabedComparison(const FlatSeabedComparison&) = delete;
  FlatSeabedComparison& operator=(const FlatSeabedComparison&) = delete;

  // Traces the reference through `hostFrame`'s water texture (its sun, optics, water).
  bool prepare(const postfx::FrameDesc& hostFrame, const CausticReportSettings& settings,
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

  CausticReportSettings settings_;
  postfx::FrameDesc frame_;
  std::unique_ptr<PlaneGbuffer> gbuffer_;
  std::unique_ptr<ReportTarget> target_;
  ocean::reference::ReferenceDesc desc_;
  ocean::reference::ReferenceResult reference_;
  double cosine_ = 1.0;  // N.L of the floor: the refracted sun's cosine to the vertical
};

// `hostFrame`: the sample's frame (sun, water texture and statistics, optics).
bool measureCaustics(const postfx::FrameDesc& hostFrame, const CausticReportSettings& settings,
                     std::vector<Row>& rows, std::string& note, std::string& error);

}  // namespace ocean::report
