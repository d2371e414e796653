#version 450 core
// Reflected caustics, step 1 of 3: every water grid point's mirrored sun ray onto one height layer
// above the level, into the buffer the wavefront area ratio's triangle and point draws read
// (the same two vec4s per point: (landing xy, beam xy) in irradiance texels from the window
// corner, then (Fresnel reflectance relative to flat water's, the ray's drift per metre of rise
// xy, 0)). The draws then add the beam area over the landing area, folds summed, exactly as
// under the water, and (compiled with POSTFX_GRID_DRIFT) that light times the drift.
// Compile-time switch: POSTFX_WATER_SINGLE_2D.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/reflected_caustics/postfx_reflected_caustics.h"

layout(local_size_x = 16, local_size_y = 16) in;

#include "postfx/seabed_caustics/grid_water.glsl"

// xy: grid point (0, 0) relative to the window corner (m); z: grid spacing (m); w: the layer's
// height above the level (m).
layout(location = 5) uniform vec4 grid;
layout(location = 6) uniform vec4 towardSun;  // xyz: unit vector to the sun; w: IOR
// x: 1 / flat-water reflectance; y: texels per metre
layout(location = 7) uniform vec4 scales;
layout(location = 9) uniform int pointsPerSide;
// xz: the window's corner relative to the camera (m); y: the level relative to the camera (m)
layout(location = 10) uniform vec3 cornerFromCamera;

#if POSTFX_SHADOW_MASK
// The host's sun shadow map at each grid point: water in the shade of a pier or hull mirrors
// nothing, and the receivers it would have lit get what the sunlit water around it sends.
layout(binding = POSTFX_UNIT_SHADOW) uniform sampler2DShadow sunShadowMap;
#include "postfx/seabed_caustics/sun_visibility.glsl"
#endif

layout(std430, binding = POSTFX_STORAGE_GRID_POINTS) writeonly buffer GridPoints {
  vec4 gridPoints[];
};

void main() {
  ivec2 index = ivec2(gl_GlobalInvocationID.xy);
  if (index.x >= pointsPerSide || index.y >= pointsPerSide) return;
  vec2 local = grid.xy + vec2(index) * grid.z;
  vec3 surface = gridWater(index);
  vec3 n = waterNormalFromSlopes(surface.xy);
  float h = sanitizeHeight(surface.z);
  vec4 ray = mirroredSunRay(n, towardSun.xyz, towardSun.w, scales.x);
  vec3 hit = reflectToLayer(local, h, ray, grid.w);
  vec2 beam = beamPosition(local, surface.z, towardSun.xz / towardSun.y);
  int i = 2 * (index.y * pointsPerSide + index.x);
  gridPoints[i] = vec4(hit.xy, beam) * scales.y;
  vec2 drift = mirroredDrift(ray, -towardSun.xz / towardSun.y);
#if POSTFX_SHADOW_MASK
  if (hit.z > 0.0) {
    vec3 water = vec3(local.x + cornerFromCamera.x, cornerFromCamera.y + h,
                      local.y + cornerFromCamera.z);
    hit.z *= sunVisibility(water, n);
  }
#endif
  gridPoints[i + 1] = vec4(hit.z, drift, 0.0);
}
