#version 450 core
// Tile irradiance, step 1 of 2: a grid of water points (CausticsSettings::tilePointsPerTexel
// per irradiance texel and side, each with its cell's mean slopes and height from the water's
// mip chain) of one cascade refracts the sun onto every depth layer and adds its flux, split
// bilinearly over the four nearest irradiance texels, into integer accumulators (periodic: the
// tile wraps). Why points and not the refracted triangles of the window model: the bilinear
// split spreads each point's flux over its neighbours, so the density stays smooth where the
// light converges, which is where caustics are; the mesh's exactness in the dark parts costs a
// rasterised triangle per cell and layer, several times this pass on a CPU rasteriser.
// With POSTFX_TILE_FOOTPRINT (TileIrradiancePass turns it on where the points are at least as
// dense as the water's texels, so nothing unresolved softens the pattern) each point's flux is
// spread over its refracted footprint instead, a box as wide as its neighbours' landings.
// Compile-time switches: POSTFX_WATER_SINGLE_2D, POSTFX_TILE_FOOTPRINT.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"

layout(local_size_x = 8, local_size_y = 8) in;

#include "postfx/seabed_caustics/water_texture.glsl"

layout(std430, binding = POSTFX_STORAGE_TILE_ACCUMULATORS) buffer TileAccumulators {
  uint accumulators[];
};

layout(location = 0) uniform int cascade;
// x: source points per side, y: irradiance texels per side (a power of two), z: tile (m),
// w: first accumulator layer of this cascade.
layout(location = 1) uniform vec4 grid;
layout(location = 2) uniform vec4 towardSun;  // xyz: unit vector to the sun; w: IOR
// xy: flat-water drift per metre of depth; z: 1 / flat-water transmittance; w: fixed-point flux
// of one point under flat water.
layout(location = 3) uniform vec4 flatWater;
layout(location = 4) uniform int layers;
layout(location = 5) uniform float depths[TILE_MAX_LAYERS];
// Water mip level of one point's cell: its mean slopes when points are sparser than texels.
layout(location = 13) uniform float sourceLod;

void addFlux(int layer, ivec2 texel, int mask, int side, float value) {
  ivec2 t = texel & ivec2(mask);
  uint index = uint((layer * side + t.y) * side + t.x);
  atomicAdd(accumulators[index], uint(value + 0.5));
}

// Landing position of the water point at `uv` with `surface` on layer k, in irradiance texels
// (continuous: texel t covers [t, t + 1)).
vec2 landingTexel(vec2 uv, vec3 surface, int k) {
  vec2 offset = tileLandingOffset(surface, towardSun.xyz, towardSun.w, flatWater.xy, depths[k]);
  return (uv + offset / grid.z) * grid.y;
}

vec3 waterAt(vec2 uv) {
  return textureLod(waterSurface, WATER_COORD(uv, cascade), sourceLod).rgb;
}

#if POSTFX_TILE_FOOTPRINT
// Overlap of the box [lo, lo + width] with texel cell [t, t + 1), over the width: the share of
// a point's flux the cell gets along one axis (width 1 gives the bilinear weights).
float boxShare(float lo, float width, float t) {
  return max(min(lo + width, t + 1.0) - max(lo, t), 0.0) / width;
}

// Widest footprint a point is spread over, in texels per axis: where the light is spread over
// 16 times flat water's area the rest is too dark to show a grid. A SIMD group runs its widest
// lane's loop; 2 costs less and leaves dots in the darkest cells (docs/measurements.md).
const float kMaxFootprint = 4.0;
const int kMaxFootprintCells = 5;  // cells a box of kMaxFootprint texels can touch per axis

// The point's flux over the box of `width` texels centred on q, cell by cell.
void addFootprint(int layer, vec2 q, vec2 width, int mask, int side, float flux) {
  vec2 lo = q - 0.5 * width;
  vec2 first = floor(lo);
  ivec2 c = ivec2(first);
  for (int j = 0; j < kMaxFootprintCells; ++j) {
    float wz = boxShare(lo.y, width.y, first.y + float(j));
    if (!(wz > 0.0)) break;
    for (int i = 0; i < kMaxFootprintCells; ++i) {
      float wx = boxShare(lo.x, width.x, first.x + float(i));
      if (!(wx > 0.0)) break;
      addFlux(layer, c + ivec2(i, j), mask, side, flux * wx * wz);
    }
  }
}
#endif

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  int points = int(grid.x);
  if (id.x >= points || id.y >= points) return;
  vec2 uv = (vec2(id) + 0.5) / grid.x;
  vec3 surface = waterAt(uv);
  float flux = tileLandingFlux(surface, towardSun.xyz, towardSun.w, flatWater.z) * flatWater.w;
  if (!(flux > 0.0)) return;
#if POSTFX_TILE_FOOTPRINT
  // Where the neighbouring points land spans this point's cell after refraction: the footprint
  // its flux covers (the wavefront's area ratio, per point). Where the light diverges it is
  // wider than a texel, and a bilinear split alone leaves a grid of dots in the dark cells.
  // The sampler wraps, and the unwrapped coordinates keep the differences continuous.
  vec2 du = vec2(1.0 / grid.x, 0.0), dv = vec2(0.0, 1.0 / grid.x);
  vec3 west = waterAt(uv - du), east = waterAt(uv + du);
  vec3 south = waterAt(uv - dv), north = waterAt(uv + dv);
#endif
  int side = int(grid.y);
  int mask = side - 1;
  int base = int(grid.w);
  for (int k = 0; k < TILE_MAX_LAYERS; ++k) {
    if (k >= layers) break;
    vec2 q = landingTexel(uv, surface, k);
    // Far outside any tile (absurd slopes): the float no longer resolves a texel; drop it.
    if (!(abs(q.x) < 1e6 && abs(q.y) < 1e6)) continue;
#if POSTFX_TILE_FOOTPRINT
    vec2 ex = 0.5 * (landingTexel(uv + du, east, k) - landingTexel(uv - du, west, k));
    vec2 ez = 0.5 * (landingTexel(uv + dv, north, k) - landingTexel(uv - dv, south, k));
    // A box with the footprint's variance along each axis (the parallelogram spanned by ex and
    // ez has variance (ex.x^2 + ez.x^2) / 12 along x), at least a texel wide: exactly the
    // bilinear split where the light converges or stays flat. The weights sum to 1: the flux
    // is conserved whatever the width.
    vec2 width = clamp(sqrt(ex * ex + ez * ez), vec2(1.0), vec2(kMaxFootprint));
    if (!all(lessThan(abs(ex) + abs(ez), vec2(1e6)))) width = vec2(1.0);
    addFootprint(base + k, q, width, mask, side, flux);
#else
    vec2 texel = q - 0.5;
    vec2 corner = floor(texel);
    vec2 f = texel - corner;
    ivec2 c = ivec2(corner);
    addFlux(base + k, c, mask, side, flux * (1.0 - f.x) * (1.0 - f.y));
    addFlux(base + k, c + ivec2(1, 0), mask, side, flux * f.x * (1.0 - f.y));
    addFlux(base + k, c + ivec2(0, 1), mask, side, flux * (1.0 - f.x) * f.y);
    addFlux(base + k, c + ivec2(1, 1), mask, side, flux * f.x * f.y);
#endif
  }
}
