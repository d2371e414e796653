#version 450 core
// Wavefront area ratio [4], the landing spread: each depth layer's irradiance convolved with the
// Gaussian of its landing covariance, depth^2 (J S J^T + the sun disc's), S the slope covariance
// the grid does not carry (inside its cells, every cascade: tile_irradiance_spread.comp's
// statistics of this grid's cells). The grid refracts mip-filtered slopes, so the ripples finer
// than a cell are gone from its light; in the water they scatter it, the more the deeper.
// Separable, rows then columns, one dispatch each over every layer; the xz term of the
// covariance is left out (the sun's azimuth turns the ellipse, which only the diagonal could
// follow). Taps clamp at the window's edge and reach no farther than the band over which the
// lookup fades the window out (IRRADIANCE_FADE_BAND): the window's inside never sees its edge,
// and a wider blur is cut there (its layer's light is nearly flat anyway).
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = POSTFX_UNIT_TILE_IRRADIANCE) uniform sampler2DArray source;  // level 0 read
layout(binding = POSTFX_IMAGE_TILE_IRRADIANCE, r32f) uniform writeonly image2DArray target;

// x: texels per side, y: direction (0 rows, 1 columns), z: layers
layout(location = 0) uniform ivec4 pass;
layout(location = 1) uniform float depths[TILE_MAX_LAYERS];  // m below the level
layout(location = 15) uniform float cellMetres;  // the grid's spacing (m)
#define TILE_SPREAD_READER 1
#include "postfx/seabed_caustics/tile_irradiance_spread_statistics.glsl"

// This workgroup's variance along its direction (texels^2): its invocations share one layer.
shared float groupVariance;

// Layer k's landing variance along this dispatch's direction (texels^2).
float layerVariance(int k) {
  // Landing covariance per metre^2 of depth (texels^2): the sun's disc and the cells' slopes.
  vec3 disc = tileSlotDiscCovariance(0);
  vec3 unresolved = tileSlotUnresolvedCovariance(0);
  float d = depths[k];
  // The cells' ripples scatter the light only past their folds: a ripple of wavenumber k whose
  // landing moves by s at this depth folds its light where s k > 1 (k at least pi / cell).
  // Before that it bends the light by under a cell / pi and draws a pattern finer than the
  // grid; counted as a diffuser it blurred the calm `shallow` sea (0.50 against 0.53 without
  // it) and a host's few coherent ripples at 3 m (0.62 against 0.69).
  float landingMetres = sqrt(max(0.5 * (unresolved.x + unresolved.z), 0.0)) * d / texelsPerMetre[0];
  float folded = smoothstep(1.0, 3.0, landingMetres * 3.14159265 / cellMetres);
  return ((pass.y == 0 ? disc.x : disc.z) + folded * (pass.y == 0 ? unresolved.x : unresolved.z)) *
         d * d;
}

void main() {
  ivec3 t = ivec3(gl_GlobalInvocationID);
  // Once per workgroup, not per texel: the statistics' sums are the same for all of them.
  if (gl_LocalInvocationIndex == 0u) groupVariance = layerVariance(min(t.z, pass.z - 1));
  barrier();
  int n = pass.x;
  if (t.x >= n || t.y >= n || t.z >= pass.z) return;
  float variance = groupVariance;
  ivec2 step = pass.y == 0 ? ivec2(1, 0) : ivec2(0, 1);
  float value = 0.0;
  if (!(variance > 1e-4)) {
    value = texelFetch(source, t, 0).r;
  } else {
    int r = min(int(ceil(3.0 * sqrt(variance))), int(float(n) * IRRADIANCE_FADE_BAND));
    float k = -0.5 / variance, sum = 0.0, weights = 0.0;
    for (int i = -r; i <= r; ++i) {
      ivec2 q = clamp(t.xy + step * i, ivec2(0), ivec2(n - 1));
      float w = exp(float(i * i) * k);
      sum += w * texelFetch(source, ivec3(q, t.z), 0).r;
      weights += w;
    }
    value = sum / weights;
  }
  imageStore(target, t, vec4(value));
}
