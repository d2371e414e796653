#include "local_water_rows.h"

#include <cstdio>

#include "pattern_sweep.h"

namespace ocean {

bool measureLocalWaterRows(const Options& base, const LocalWaterReportSettings& settings,
                           std::vector<report::Row>& rows, std::string& note, std::string& error) {
  PatternSweep sweep;
  sweep.name = "local water";
  sweep.preset = "pool";
  sweep.width = settings.width;
  sweep.height = settings.height;
  sweep.timedFrames = settings.timedFrames;
  // No god rays in any of the frames: flat water's frame (ray deviation at tau 0) would light
  // its shafts otherwise than the others, and they would count as caustic light.
  sweep.frame = [](Options& o) { o.godRays = false; };
  sweep.unlit = [](Options& o) {
    o.caustics = false;
    o.objectCaustics = false;
  };
  // Flat water's frame: the regions flat, the plugin's factor 1 (ray deviation at tau 0).
  sweep.flat = [](Options& o) {
    o.objectCaustics = false;
    o.flatLocalWater = true;
    o.rayDeviationCaustics = true;
    o.tau = 0.0;
  };
  sweep.setting = [](Options& o, int grid) {
    o.localWaterGrid = grid;
    o.objectCaustics = false;
  };
  sweep.values = settings.grids;
  sweep.pass = postfx::Pass::LocalWater;
  sweep.method = "local water, the pool (Replace)";
  sweep.settingLabel = "grid";
  PatternSweepTrace trace;
  if (!measurePatternSweep(base, sweep, rows, trace, error)) return false;
  char text[512];
  std::snprintf(text, sizeof(text),
                "Local water: the pool preset at %dx%d (its simulation at rest 4 s before t = "
                "%.3g s, then its drops and ball), traced once through the simulation's texture "
                "(%.3g photons in %d batches, lit-pixel noise p99 %.2f %%, %s); each grid's "
                "pattern (added light / flat water's) against it, the pass timed over %d frames "
                "with the floor.",
                settings.width, settings.height, base.timeSeconds, trace.photons, trace.batches,
                100.0 * trace.noiseQuantile, trace.converged ? "converged" : "NOT converged",
                settings.timedFrames);
  note = text;
  return true;
}

}  // namespace ocean
