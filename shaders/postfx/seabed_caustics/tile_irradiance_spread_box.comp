#version 450 core
// Tile irradiance, unresolved-slope spread, step 2 of 3 (postfx/seabed_caustics/postfx_tile_irradiance.h): each
// depth layer's periodic field convolved with the Gaussian of its landing covariance C, as 1D
// Gaussians along grid lines of the tile whose covariances add up to C (rows and columns; with
// a diagonal too where C's axes are turned away from the grid's: C = alpha x x^T + beta z z^T +
// gamma d d^T, d the diagonal along the sign of C's xz term), each as two box filters of
// running sums and a 3-tap for the rest (O(1) a texel: a wide blur costs what a narrow one does). One dispatch
// per direction, for every cascade and layer at once; one invocation sweeps one line of one
// layer twice (the boxes), between the two copies of the blur buffer (its own line only: no
// barrier within a direction). The first direction reads the accumulators; every direction
// ends in copy 1, which tile_irradiance_spread_pack.comp writes into the irradiance array.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"  // POSTFX_MAX_CASCADES (its block goes unused here)
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"

layout(local_size_x = 64) in;

layout(std430, binding = POSTFX_STORAGE_TILE_ACCUMULATORS) readonly buffer TileAccumulators {
  uint accumulators[];
};
// ((copy * slots + slot) * layers + layer) * n^2 + z * n + x: one float a layer and texel.
layout(std430, binding = POSTFX_STORAGE_TILE_BLUR) buffer TileBlur {
  float blur[];
};
#define TILE_SPREAD_READER 1
#include "postfx/seabed_caustics/tile_irradiance_spread_statistics.glsl"

// x: texels per side n (a power of two), y: direction (0 rows, 1 columns, 2 the diagonal),
// z: irradiance slots, w: depth layers per slot
layout(location = 0) uniform ivec4 pass;
layout(location = 1) uniform float depths[TILE_MAX_LAYERS];  // m below the level

// Two boxes of half-widths `halfWidths` (odd widths wl or wl + 2: Kovesi's split of a Gaussian
// into boxes, here the widest pair whose variances, (w^2 - 1) / 12 each, stay within
// `variance`, texels^2 along the line's own steps) and the 3-tap [a, 1 - 2a, a] each sweep adds
// for the rest (2a each): without it a blur under a texel's variance would round to no blur
// at all, and every wider one to the variance of whole boxes.
void spreadPlan(float variance, out ivec2 halfWidths, out float a) {
  halfWidths = ivec2(0);
  a = 0.0;
  if (!(variance > 1e-4)) return;
  int wl = max(int(floor(sqrt(6.0 * variance + 1.0))), 1);
  if ((wl & 1) == 0) wl -= 1;
  float narrow = (float(wl * wl) - 1.0) / 12.0, wide = (float((wl + 2) * (wl + 2)) - 1.0) / 12.0;
  bool oneWide = narrow + wide <= variance;
  float rest = variance - (oneWide ? narrow + wide : 2.0 * narrow);
  int limit = pass.x / 2 - 1;  // no wider than the tile
  halfWidths = min(ivec2((wl - 1) / 2, (oneWide ? wl + 1 : wl - 1) / 2), ivec2(limit));
  a = clamp(0.25 * rest, 0.0, 0.5);
}

int n, mask, line, layer, slot, diagonalSign;

// Tile texel of step i along this invocation's line (periodic).
ivec2 lineTexel(int i) {
  if (pass.y == 0) return ivec2(i & mask, line);
  if (pass.y == 1) return ivec2(line, i & mask);
  return ivec2(i & mask, (line + diagonalSign * i) & mask);
}

// This layer's texel t in copy `copy`, or in the accumulators (copy < 0).
uint texelIndex(int copy, ivec2 t) {
  int plane = copy < 0 ? slot * pass.w + layer : (copy * pass.z + slot) * pass.w + layer;
  return uint((plane * n + t.y) * n + t.x);
}

float valueAt(int copy, int i) {
  uint index = texelIndex(copy, lineTexel(i));
  return copy < 0 ? float(accumulators[index]) * (1.0 / TILE_FIXED_POINT) : blur[index];
}

// One box of half-width r along the line, then the 3-tap [a, 1 - 2a, a], from copy `from` to
// copy `to`: running sums, O(1) a texel whatever the width.
void boxSweep(int r, float a, int from, int to) {
  float invWidth = 1.0 / float(2 * r + 1);
  float sum = 0.0;
  for (int t = -r - 1; t <= r - 1; ++t) sum += valueAt(from, t);
  float previous = sum * invWidth;  // the box about step -1
  sum += valueAt(from, r) - valueAt(from, -r - 1);
  float current = sum * invWidth;  // about step 0
  for (int i = 0; i < n; ++i) {
    sum += valueAt(from, i + r + 1) - valueAt(from, i - r);
    float next = sum * invWidth;
    blur[texelIndex(to, lineTexel(i))] = a * (previous + next) + (1.0 - 2.0 * a) * current;
    previous = current;
    current = next;
  }
}

void main() {
  n = pass.x;
  mask = n - 1;
  line = int(gl_GlobalInvocationID.x);
  layer = int(gl_GlobalInvocationID.y);
  slot = int(gl_GlobalInvocationID.z);
  if (line >= n) return;
  vec3 c = tileSlotCovariance(slot);
  bool diagonal = tileSpreadNeedsDiagonal(c);
  if (pass.y == 2 && !diagonal) return;  // C's axes are the grid's: rows and columns hold it
  float xz = diagonal ? abs(c.y) : 0.0;
  diagonalSign = c.y >= 0.0 ? 1 : -1;
  // Variance along the line's own steps per metre^2 of depth: alpha, beta, and gamma / 2 for a
  // diagonal step of length sqrt(2).
  float perDepth = pass.y == 0 ? max(c.x - xz, 0.0) : (pass.y == 1 ? max(c.z - xz, 0.0) : xz);
  float variance = perDepth * depths[layer] * depths[layer];
  // Rows: accumulators -> copy 0 -> copy 1; columns and the diagonal: copy 1 -> 0 -> 1.
  int from = pass.y == 0 ? -1 : 1;
  ivec2 halfWidths;
  float a;
  spreadPlan(variance, halfWidths, a);
  boxSweep(halfWidths.x, a, from, 0);
  boxSweep(halfWidths.y, a, 0, 1);
}
