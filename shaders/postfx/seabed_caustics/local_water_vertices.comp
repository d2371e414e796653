#version 450 core
// Local water (Feature::LocalWater), step 1 of the region's wavefront area ratio: every grid
// point of region's rectangle refracted onto a receiver layer, into the buffer the wavefront area
// ratio's two draws read (wavefront_area_ratio.vert, wavefront_area_ratio_points.vert). All in
// the region's local frame (a rotation about y keeps refraction as it is): the surface is the
// region's texture (clamped) plus, in Add mode, the cascades beneath it; receiver positions are
// written in entry-point texels (the landing minus flat water's drift to the layer), so that
// every layer of the region is indexed the same way.
// Compile-time switch: POSTFX_WATER_SINGLE_2D.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"

layout(local_size_x = 16, local_size_y = 16) in;

#include "postfx/seabed_caustics/water_texture.glsl"
layout(binding = POSTFX_UNIT_LOCAL_SURFACE) uniform sampler2D regionSurface;

// Per cascade: xy = uv of grid point (0, 0) (reduced modulo the tile in double), z = the mip
// level matching the grid spacing; cascadeStep: uv per grid step along i (xy) and j (zw).
layout(location = 0) uniform vec4 cascadeGrid[POSTFX_MAX_CASCADES];
layout(location = 4) uniform vec4 cascadeStep[POSTFX_MAX_CASCADES];
// Cascades read (0: Replace mode); whether the region's texture is added (0: Add mode's field
// of the sea alone).
layout(location = 8) uniform ivec2 sources;
// xy: local position of grid point (0, 0) (m); zw: grid spacing along u and v (m).
layout(location = 9) uniform vec4 grid;
// xy: region texture uv of grid point (0, 0); zw: uv per grid step.
layout(location = 10) uniform vec4 surfaceGrid;
layout(location = 11) uniform vec4 towardSun;  // xyz: unit vector to the sun in LOCAL axes; w: IOR
// x: 1 / flat-water transmittance; y: receiver depth below the level (m); zw: texels per metre
// along u and v
layout(location = 12) uniform vec4 scales;
// xy: entry-point corner of the texture at this layer's depth (local m: the window corner plus
// flat water's drift to this depth); zw: the window corner for the beam (local m).
layout(location = 13) uniform vec4 corners;
layout(location = 14) uniform int pointsPerSide;
// The local u axis in world xz: rotates the cascades' world slopes into the local frame.
layout(location = 15) uniform vec2 axisU;

layout(std430, binding = POSTFX_STORAGE_GRID_POINTS) writeonly buffer GridPoints {
  vec4 gridPoints[];
};

void main() {
  ivec2 index = ivec2(gl_GlobalInvocationID.xy);
  if (index.x >= pointsPerSide || index.y >= pointsPerSide) return;
  vec2 local = grid.xy + vec2(index) * grid.zw;
  vec3 sea = vec3(0.0);
  for (int c = 0; c < POSTFX_MAX_CASCADES; ++c) {
    if (c >= sources.x) break;
    vec2 uv = cascadeGrid[c].xy + float(index.x) * cascadeStep[c].xy +
              float(index.y) * cascadeStep[c].zw;
    sea += textureLod(waterSurface, WATER_COORD(uv, c), cascadeGrid[c].z).rgb;
  }
  // World slopes (dh/dx, dh/dz) to local (dh/du, dh/dv): the gradient's components along u, v.
  vec2 axisV = vec2(-axisU.y, axisU.x);
  vec3 surface = vec3(dot(sea.xy, axisU), dot(sea.xy, axisV), sea.z);
  if (sources.y != 0)
    surface += textureLod(regionSurface, surfaceGrid.xy + vec2(index) * surfaceGrid.zw, 0.0).rgb;
  vec3 hit = refractToReceiver(local, surface, towardSun.xyz, towardSun.w, scales.x, scales.y);
  vec2 beam = beamPosition(local, surface.z, towardSun.xz / towardSun.y);
  int i = 2 * (index.y * pointsPerSide + index.x);
  gridPoints[i] = vec4((hit.xy - corners.xy) * scales.zw, (beam - corners.zw) * scales.zw);
  gridPoints[i + 1] = vec4(hit.z, 0.0, 0.0, 0.0);
}
