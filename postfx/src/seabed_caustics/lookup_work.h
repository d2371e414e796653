#pragma once
// The texture fetches of the seabed light's lookups at one point, on their full path (the point
// under the water, every cascade contributing, inside every window and region that covers it):
// what the caustics pass makes per pixel and the god rays per sample, stated for the work
// account (core/work_account.h) from the shaders they mirror.
#include <postfx/postfx.h>

namespace postfx::detail {

// water_sampling.glsl, cascadeSlopes: one textureLod per cascade and projection (three
// projections on walls with Feature::TriplanarWalls, one otherwise).
inline int waterSlopeFetches(int cascades, int projections) {
  return cascades * projections;
}

// tile_irradiance_lookup.glsl, tileIrradianceAt: `groups` fetches of the field for each cascade
// in `mask`, and before each cascade c > 0 that a later one needs (mask >> c nonzero, c <
// cascades) one fetch of cascade c - 1's surface (its refraction moves the next one's light).
inline int tileIrradianceFetches(int mask, int groups, int cascades, int slots) {
  int n = (mask & 1) != 0 ? groups : 0;
  for (int c = 1; c < slots; ++c)
    if ((mask >> c) != 0 && c < cascades) n += 1 + (((mask >> c) & 1) != 0 ? groups : 0);
  return n;
}

// wavefront_area_ratio_lookup.glsl, physicalIrradiance: the two depth layers around the point,
// each one filtered fetch and the four B-spline taps of level 0 (where the footprint is under a
// texel).
inline constexpr int kWindowFetches = 2 * (1 + 4);

// local_water_lookup.glsl, localWaterIrradiance: for every region covering the point, its two
// layers as the window's (10), twice in LocalWaterMode::Add (the joint field and the sea's own).
inline int localWaterFetches(const FrameDesc& frame) {
  int n = 0;
  if (frame.water.localWater == nullptr) return 0;
  for (int r = 0; r < frame.water.localWaterCount; ++r)
    n += frame.water.localWater[r].mode == LocalWaterMode::Replace ? kWindowFetches
                                                                   : 2 * kWindowFetches;
  return n;
}

// sun_visibility.glsl: one filtered comparison of the shadow map.
inline constexpr int kShadowFetches = 1;

}  // namespace postfx::detail
