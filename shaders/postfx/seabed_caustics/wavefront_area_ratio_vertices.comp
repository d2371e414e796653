#version 450 core
// Wavefront area-ratio caustics [4], step 1 of 3: every surface grid point refracted
// onto the receiver, once per layer, into a buffer both draws read (each grid point is shared
// by up to six triangles: computed once, not per triangle). Per point, two vec4s: (receiver xy,
// beam xy) in irradiance texels from the window corner, and (transmittance ratio, 0, 0, 0).
// Compile-time switch: POSTFX_WATER_SINGLE_2D.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"

layout(local_size_x = 16, local_size_y = 16) in;

#include "postfx/seabed_caustics/grid_water.glsl"

// xy: grid point (0, 0) relative to the window corner (m); z: grid spacing (m); w: receiver
// depth below the level (m).
layout(location = 5) uniform vec4 grid;
layout(location = 6) uniform vec4 towardSun;  // xyz: unit vector to the sun; w: IOR
// x: 1 / flat-water transmittance; y: texels per metre
layout(location = 7) uniform vec4 scales;
layout(location = 9) uniform int pointsPerSide;

layout(std430, binding = POSTFX_STORAGE_GRID_POINTS) writeonly buffer GridPoints {
  vec4 gridPoints[];
};

void main() {
  ivec2 index = ivec2(gl_GlobalInvocationID.xy);
  if (index.x >= pointsPerSide || index.y >= pointsPerSide) return;
  vec2 local = grid.xy + vec2(index) * grid.z;
  vec3 surface = gridWater(index);
  vec3 hit = refractToReceiver(local, surface, towardSun.xyz, towardSun.w, scales.x, grid.w);
  vec2 beam = beamPosition(local, surface.z, towardSun.xz / towardSun.y);
  int i = 2 * (index.y * pointsPerSide + index.x);
  gridPoints[i] = vec4(hit.xy, beam) * scales.y;
  gridPoints[i + 1] = vec4(hit.z, 0.0, 0.0, 0.0);
}
