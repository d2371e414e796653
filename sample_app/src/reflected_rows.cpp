#include "reflected_rows.h"

#include <cstdio>

#include "pattern_sweep.h"

namespace ocean {

bool measureReflectedRows(const Options& base, const ReflectedReportSettings& settings,
                          std::vector<report::Row>& rows, std::string& note, std::string& error) {
  PatternSweep sweep;
  sweep.name = "reflected caustics";
  sweep.preset = "harbour";
  sweep.width = settings.width;
  sweep.height = settings.height;
  sweep.timedFrames = settings.timedFrames;
  // The mirrored light alone: no seabed caustics, shafts or object caustics in any frame (the
  // trace's refracted light lands under the water, outside the compared mask, either way).
  sweep.frame = [](Options& o) {
    o.godRays = false;
    o.caustics = false;
    o.objectCaustics = false;
  };
  sweep.unlit = [](Options& o) { o.reflectedCaustics = false; };
  // Flat water's frame: the plugin given a flat sea (its mirror light R E n.l everywhere lit).
  sweep.flat = [](Options& o) { o.flatWater = true; };
  sweep.setting = [](Options& o, int grid) { o.reflectedGrid = grid; };
  sweep.values = settings.grids;
  sweep.reflected = true;
  sweep.pass = postfx::Pass::ReflectedCaustics;
  sweep.method = "reflected caustics, the harbour";
  sweep.settingLabel = "grid";
  PatternSweepTrace trace;
  if (!measurePatternSweep(base, sweep, rows, trace, error)) return false;
  char text[512];
  std::snprintf(text, sizeof(text),
                "Reflected caustics: the harbour preset at %dx%d, t = %.3g s, its light mirrored "
                "above the water traced once (%.3g photons in %d batches, mirror-lit pixel noise "
                "p99 %.2f %%, %s); each grid's pattern (added light / flat water's, over the "
                "pixels flat water's mirror light reaches) against it, the pass timed over %d "
                "frames with the floor.",
                settings.width, settings.height, base.timeSeconds, trace.photons, trace.batches,
                100.0 * trace.noiseQuantile, trace.converged ? "converged" : "NOT converged",
                settings.timedFrames);
  note = text;
  return true;
}

}  // namespace ocean
