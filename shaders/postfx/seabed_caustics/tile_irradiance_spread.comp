#version 450 core
// Tile irradiance, unresolved-slope spread, step 1 of 3 (postfx/seabed_caustics/postfx_tile_irradiance.h): the
// slope statistics of every cascade, read from the water texture itself (so any host's water,
// not only this project's ocean, gets its own spread). The wavefront area ratio's spread
// (wavefront_area_ratio_spread.comp) runs it too, with its grid's cells. Workgroup (c, p) samples every
// TILE_SPREAD_PARTS-th of TILE_SPREAD_SAMPLE_CELLS^2 point cells of cascade c, each on up to
// TILE_SPREAD_MAX_CELL_TEXELS^2 of its level-0 texels, and writes its partial sums; the blur
// (tile_irradiance_spread_box.comp) adds them up.
// Compile-time switch: POSTFX_WATER_SINGLE_2D.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"
#include "postfx/seabed_caustics/tile_irradiance_spread_statistics.glsl"

layout(local_size_x = 256) in;

#if POSTFX_WATER_SINGLE_2D
layout(binding = POSTFX_UNIT_WATER) uniform sampler2D waterSurface;
#define WATER_TEXEL(xy, layer) texelFetch(waterSurface, xy, 0)
#else
layout(binding = POSTFX_UNIT_WATER) uniform sampler2DArray waterSurface;
#define WATER_TEXEL(xy, layer) texelFetch(waterSurface, ivec3(xy, layer), 0)
#endif

layout(std430, binding = POSTFX_STORAGE_TILE_SPREAD) writeonly buffer TileSpread {
  TileSpreadPartial partials[];  // cascade * TILE_SPREAD_PARTS + part
};

// Point cells per tile side, per cascade (at least 1; fractional: the cells need not tile it).
layout(location = 0) uniform vec4 cellsPerTile;

const int kThreads = 256;
shared vec4 cellMoments[kThreads];  // xyz: second moments (xx, xz, zz) about each cell's mean; w: cells

void main() {
  int tid = int(gl_LocalInvocationIndex);
  int c = int(gl_WorkGroupID.x), part = int(gl_WorkGroupID.y);
#if POSTFX_WATER_SINGLE_2D
  ivec2 size = textureSize(waterSurface, 0);
#else
  ivec2 size = textureSize(waterSurface, 0).xy;
#endif
  // Water texels per point cell along each axis (below 1: the points are finer than the water,
  // which then has nothing inside a cell to resolve).
  float points = max(cellsPerTile[c], 1.0);
  vec2 cellTexels = vec2(size) / points;
  ivec2 perCell = clamp(ivec2(round(cellTexels)), ivec2(1), ivec2(TILE_SPREAD_MAX_CELL_TEXELS));
  vec2 texelStep = cellTexels / vec2(perCell);
  int cellsPerSide = min(int(points), TILE_SPREAD_SAMPLE_CELLS);
  int cellStride = int(points) / cellsPerSide;
  int cells = cellsPerSide * cellsPerSide;
  vec4 moments = vec4(0.0);
  for (int i = tid * TILE_SPREAD_PARTS + part; i < cells; i += kThreads * TILE_SPREAD_PARTS) {
    vec2 origin = vec2(ivec2(i % cellsPerSide, i / cellsPerSide) * cellStride) * cellTexels;
    vec2 mean = vec2(0.0);
    vec3 second = vec3(0.0);
    for (int y = 0; y < perCell.y; ++y) {
      for (int x = 0; x < perCell.x; ++x) {
        ivec2 texel = ivec2(origin + (vec2(x, y) + 0.5) * texelStep) % size;
        vec2 s = sanitizeSlopes(WATER_TEXEL(texel, c).rg);
        mean += s;
        second += vec3(s.x * s.x, s.x * s.y, s.y * s.y);
      }
    }
    float n = float(perCell.x * perCell.y);
    mean /= n;
    // E[s s^T] - m m^T within the cell
    moments += vec4(second / n - vec3(mean.x * mean.x, mean.x * mean.y, mean.y * mean.y), 1.0);
  }
  cellMoments[tid] = moments;
  memoryBarrierShared();
  barrier();
  for (int span = kThreads / 2; span > 0; span /= 2) {
    if (tid < span) {
      cellMoments[tid] += cellMoments[tid + span];
    }
    memoryBarrierShared();
    barrier();
  }
  if (tid == 0) partials[c * TILE_SPREAD_PARTS + part].cellMoments = cellMoments[0];
}
