#pragma once
// The report's reflected caustics rows: the harbour preset's light mirrored above the water at
// several grid resolutions, each frame's pattern against the harbour traced once (the mirrored
// photons; the pattern alone: added light divided by flat water's, as `compare --flat` does),
// and the ReflectedCaustics pass's time against the floor at the same size.
#include <string>
#include <vector>

#include <report_table.h>

#include "options.h"

namespace ocean {

struct ReflectedReportSettings {
  int width = 640, height = 360;
  std::vector<int> grids{256, 512, 1024, 2048};
  int timedFrames = 16;
};

// Appends one row per grid; `note` says how the reference was made. Progress on stderr.
bool measureReflectedRows(const Options& base, const ReflectedReportSettings& settings,
                          std::vector<report::Row>& rows, std::string& note, std::string& error);

}  // namespace ocean
