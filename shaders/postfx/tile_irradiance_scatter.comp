#version 450 core
// Tile irradiance, step 1 of 2: a grid of water points (CausticsSettings::tilePointsPerTexel
// per irradiance texel and side, each with its cell's mean slopes and height from the water's
// mip chain) of one cascade refracts the sun onto every depth layer and adds its flux, split
// bilinearly over the four nearest irradiance texels, into integer accumulators (periodic: the
// tile wraps). Why points and not the refracted triangles of the window model: the bilinear
// split spreads each point's flux over its neighbours, so the density stays smooth where the
// light converges, which is where caustics are; the mesh's exactness in the dark parts costs a
// rasterised triangle per cell and layer, several times this pass on a CPU rasteriser.
// Compile-time switch: POSTFX_WATER_SINGLE_2D.
#include "shared/common.h"
#include "shared/postfx_bindings.h"
#include "shared/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "shared/postfx_tile_irradiance.h"

layout(local_size_x = 8, local_size_y = 8) in;

#if POSTFX_WATER_SINGLE_2D
layout(binding = POSTFX_UNIT_WATER) uniform sampler2D waterSurface;
#define WATER_COORD(uv, layer) (uv)
#else
layout(binding = POSTFX_UNIT_WATER) uniform sampler2DArray waterSurface;
#define WATER_COORD(uv, layer) vec3(uv, float(layer))
#endif

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

void main() {
  ivec2 id = ivec2(gl_GlobalInvocationID.xy);
  int points = int(grid.x);
  if (id.x >= points || id.y >= points) return;
  vec2 uv = (vec2(id) + 0.5) / grid.x;
  vec3 surface = textureLod(waterSurface, WATER_COORD(uv, cascade), sourceLod).rgb;
  float flux = tileLandingFlux(surface, towardSun.xyz, towardSun.w, flatWater.z) * flatWater.w;
  if (!(flux > 0.0)) return;
  int side = int(grid.y);
  int mask = side - 1;
  int base = int(grid.w);
  for (int k = 0; k < TILE_MAX_LAYERS; ++k) {
    if (k >= layers) break;
    vec2 offset = tileLandingOffset(surface, towardSun.xyz, towardSun.w, flatWater.xy, depths[k]);
    vec2 texel = (uv + offset / grid.z) * grid.y - 0.5;
    vec2 corner = floor(texel);
    vec2 f = texel - corner;
    // Far outside any tile (absurd slopes): the float no longer resolves a texel; drop it.
    if (!(abs(corner.x) < 1e6 && abs(corner.y) < 1e6)) continue;
    ivec2 c = ivec2(corner);
    addFlux(base + k, c, mask, side, flux * (1.0 - f.x) * (1.0 - f.y));
    addFlux(base + k, c + ivec2(1, 0), mask, side, flux * f.x * (1.0 - f.y));
    addFlux(base + k, c + ivec2(0, 1), mask, side, flux * (1.0 - f.x) * f.y);
    addFlux(base + k, c + ivec2(1, 1), mask, side, flux * f.x * f.y);
  }
}
