#pragma once
// The report's local water rows: the pool preset's region at several grid resolutions, each
// frame's pattern against the pool traced once (the pattern alone: added light divided by flat
// water's, as `compare --flat` does), and the LocalWater pass's time against the floor at the
// same size.
#include <string>
#include <vector>

#include <report_table.h>

#include "options.h"

namespace ocean {

struct LocalWaterReportSettings {
  int width = 640, height = 360;
  std::vector<int> grids{64, 128, 256, 512, 1024};
  int timedFrames = 16;
};

// Appends one row per grid; `note` says how the reference was made. Progress on stderr.
bool measureLocalWaterRows(const Options& base, const LocalWaterReportSettings& settings,
                           std::vector<report::Row>& rows, std::string& note, std::string& error);

}  // namespace ocean
