#pragma once
// An error-against-time sweep of one preset's light: the frame without the light (the base), the
// same frame with the light traced once (the reference, and which pixels it lights), flat
// water's frame, then one frame per value of a swept setting, each compared with the reference
// pattern-only (added light / flat water's, as `compare --flat` does) and its pass timed against
// the floor over still frames. The local water and reflected caustics rows are such sweeps.
#include <cstdint>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <report_table.h>

#include "options.h"

namespace ocean {

struct PatternSweep {
  std::string name;    // for progress: "local water"
  std::string preset;  // every frame's
  int width = 640, height = 360;
  int timedFrames = 16;
  void (*frame)(Options&) = nullptr;  // applied to every frame (god rays off, ...)
  void (*unlit)(Options&) = nullptr;  // the base frame: the measured light off
  void (*flat)(Options&) = nullptr;   // flat water's frame of the light
  void (*setting)(Options&, int) = nullptr;
  std::vector<int> values;
  // Compare the light the water mirrors up (the trace's reflected light and its mask) instead of
  // the refracted light under the water.
  bool reflected = false;
  postfx::Pass pass = postfx::Pass::Caustics;
  std::string method;        // each row's series
  std::string settingLabel;  // "grid": rows read "grid 256"
};

// How the reference was traced, for the caller's note.
struct PatternSweepTrace {
  double photons = 0.0;
  int batches = 0;
  double noiseQuantile = 0.0;
  bool converged = false;
};

// Appends one row per value. Progress on stderr.
bool measurePatternSweep(const Options& base, const PatternSweep& sweep,
                         std::vector<report::Row>& rows, PatternSweepTrace& trace,
                         std::string& error);

}  // namespace ocean
