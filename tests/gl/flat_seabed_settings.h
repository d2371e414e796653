#pragma once
// The flat-seabed comparison the tile-irradiance tests run against converged light tracing: the
// report's seabed `depth` metres below the level at 128 x 96 pixels, 4-pixel bins, traced to a
// 5 % median bin error (half the time of the report's 1 %).
#include <flat_seabed_comparison.h>

namespace postfxtest {

inline ocean::validation::FlatSeabedSettings flatSeabedTestSettings(double depth) {
  ocean::validation::FlatSeabedSettings settings;
  settings.width = 128;
  settings.height = 96;
  settings.binPixels = 4;
  settings.referenceError = 0.05;
  settings.receiverDepth = depth;
  return settings;
}

}  // namespace postfxtest
