// Local water regions (postfx/local_water.h), shared by C++ and GLSL: the uniform block the
// caustics and god-ray passes read them through, and the math of their lookup, so that the tests
// evaluate exactly what the shaders do. Only vec4 members: std140 adds no padding and the C++
// struct matches byte for byte.
#ifndef POSTFX_SHARED_LOCAL_WATER_H
#define POSTFX_SHARED_LOCAL_WATER_H
#include "shared/common.h"

#define POSTFX_LOCAL_WATER_BLOCK_BINDING 2
#define POSTFX_MAX_LOCAL_WATER 4

SHARED_BEGIN

#ifdef __cplusplus
struct LocalWaterBlock {
#else
layout(std140, binding = POSTFX_LOCAL_WATER_BLOCK_BINDING) uniform LocalWaterBlock {
#endif
  vec4 count;  // x: regions this frame (0: the lookup returns the periodic light); yzw: unused
  // Per region: xy: its centre relative to the camera (world xz, m, from double); zw: its
  // local u axis in world xz, (cos r, -sin r) (v is (sin r, cos r)).
  vec4 frame[POSTFX_MAX_LOCAL_WATER];
  // xy: half its size (m); z: edge blend (m); w: 1 for LocalWaterMode::Replace, 0 for Add.
  vec4 extent[POSTFX_MAX_LOCAL_WATER];
  // xy: the corner of the region's irradiance layers in entry-point coordinates (local m);
  // zw: 1 / their extent (1/m) along u and v.
  vec4 window[POSTFX_MAX_LOCAL_WATER];
  // xy: flat water's landing drift per metre of depth, in local axes (a receiver's light entered
  // at its position minus drift * depth); z: depth layers; w: log2(texels per metre).
  vec4 drift[POSTFX_MAX_LOCAL_WATER];
  vec4 depths[2 * POSTFX_MAX_LOCAL_WATER];  // region r: [2r] layers 0-3, [2r + 1] layers 4-7 (m)
  // x: the region's first layer in the one texture all regions share; y: its share of the
  // texture's side (its layers fill the corner [0, y) of each); z: the texture's side in texels.
  vec4 lookup[POSTFX_MAX_LOCAL_WATER];
#ifdef __cplusplus
};
static_assert(sizeof(LocalWaterBlock) == (1 + 7 * POSTFX_MAX_LOCAL_WATER) * 16,
              "LocalWaterBlock must match its std140 layout");
#else
}
lw;
#endif

// Where the light of a receiver at camera-relative xz, depthBelow under the level, entered the
// water in region-local metres: its position in the region's frame minus the flat drift.
SHARED_FN vec2 localWaterEntry(vec2 xz, float depthBelow, vec4 regionFrame, vec4 regionDrift) {
  vec2 d = xz - vec2(regionFrame.x, regionFrame.y);
  vec2 axisU = vec2(regionFrame.z, regionFrame.w);
  vec2 axisV = vec2(-axisU.y, axisU.x);
  return vec2(dot(d, axisU), dot(d, axisV)) - vec2(regionDrift.x, regionDrift.y) * depthBelow;
}

// How much of the region's light a receiver whose light entered at `entry` takes: 1 inside the
// rectangle shrunk by the blend, 0 outside it, smoothstep between (a hard step at blend 0).
SHARED_FN float localWaterWeight(vec2 entry, vec4 regionExtent) {
  vec2 inside = vec2(regionExtent.x, regionExtent.y) - abs(entry);
  float distance = min(inside.x, inside.y);
  float blend = regionExtent.z;
  if (!(blend > 0.0f)) return distance > 0.0f ? 1.0f : 0.0f;
  float t = clamp(distance / blend, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// The light under a region from the periodic light and the region's two fields: Replace takes
// the region's own (`joint`) with weight w; Add corrects the periodic light by what the region's
// heights change (`joint` - `seaOnly`, both refracted by the same grid, so a region of zero
// height gives exactly 0), never below 0.
SHARED_FN float localWaterLight(float periodic, float joint, float seaOnly, float weight,
                                float replace) {
  if (replace > 0.5f) return periodic + (joint - periodic) * weight;
  return max(periodic + weight * (joint - seaOnly), 0.0f);
}

SHARED_END

#endif
