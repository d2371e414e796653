#pragma once
// The report's caustics rows: the tile irradiance (the default model) at several tile sizes and
// layer counts, the ray-deviation coefficient at several tau, with and without the reflection
// term, with and without cascade skipping, and the wavefront area ratio window at
// each grid resolution, each timed and compared on the flat seabed (flat_seabed_comparison.h)
// with converged CPU light tracing through the same water texture the GPU used, at each of the
// sizes asked for.
#include <string>
#include <vector>

#include <flat_seabed_comparison.h>
#include <postfx/postfx.h>

#include "report_table.h"

namespace ocean::report {

struct CausticReportSettings {
  validation::FlatSeabedSettings seabed;
  int timedFrames = 16;
  std::vector<int> physicalGrids = {64, 128, 256, 512, 1024};
  // false: the tile-irradiance variants and the physical model's middle grid only (a size the
  // plot does not show, measured for the table).
  bool everyModel = true;
};

// `hostFrame`: the sample's frame (sun, water texture and statistics, optics). One comparison
// (its own traced reference) per entry of `sizes`; each row carries its size.
bool measureCaustics(const postfx::FrameDesc& hostFrame,
                     const std::vector<CausticReportSettings>& sizes, std::vector<Row>& rows,
                     std::string& note, std::string& error);

}  // namespace ocean::report
