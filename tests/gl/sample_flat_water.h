#pragma once
// The plugin set to flat water's light, the sample's `--caustics-model ray-deviation --tau 0`:
// a factor of 1 everywhere, so the seabed light is exactly the direct sun below a flat surface.
// No god rays and no object caustics: the tests that use it hold the surface light alone.
#include "options.h"

namespace sampletest {

inline ocean::Options flatWaterOptions() {
  ocean::Options options;
  options.rayDeviationCaustics = true;
  options.tau = 0.0;
  options.godRays = false;
  options.objectCaustics = false;
  return options;
}

}  // namespace sampletest
