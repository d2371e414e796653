#pragma once
// The plugin set to flat water's light, the sample's `--caustics-model ray-deviation --tau 0`:
// a factor of 1 everywhere, so the seabed light is exactly the direct sun below a flat surface.
// No god rays and no object caustics: the tests that use it hold the surface light alone.
#include "options.h"
#include "renderer.h"

namespace sampletest {

inline ocean::Options flatWaterOptions() {
  ocean::Options options;
  options.rayDeviationCaustics = true;
  options.tau = 0.0;
  options.godRays = false;
  options.objectCaustics = false;
  return options;
}

// The renderer those tests draw with: a small frame, a cheap ocean (flat water needs none), a
// shadow map fine enough for their casters' edges.
inline ocean::RenderSettings flatWaterRenderSettings(int width, int height) {
  ocean::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.waterResolution = 64;
  settings.shadowMapSize = 1024;
  return settings;
}

}  // namespace sampletest
