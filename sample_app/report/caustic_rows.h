#pragma once
// The report's caustics rows: the seed-002 coefficient at several tau, with and without the
// reflection term, with and without cascade skipping, and the physical (wavefront area ratio)
// model at each grid resolution, each timed and compared with converged CPU light tracing
// (ocean::reference::traceSeabedCaustics) through the same water texture the GPU used.
//
// The comparison scene is a flat seabed seen straight from above, so each bin of the
// reference is a block of whole pixels: the plugin's raw caustic factor, divided by N.L, is
// averaged over the block and compared with the reference irradiance there (flat water = 1).
#include <string>
#include <vector>

#include <postfx/postfx.h>

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

// `hostFrame`: the sample's frame (sun, water texture and statistics, optics).
bool measureCaustics(const postfx::FrameDesc& hostFrame, const CausticReportSettings& settings,
                     std::vector<Row>& rows, std::string& note, std::string& error);

}  // namespace ocean::report
