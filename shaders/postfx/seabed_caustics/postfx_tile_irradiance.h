// Caustic irradiance per water cascade on its periodic tile (the TileIrradiance model), shared by
// C++ and GLSL: the scatter pass's per-point refraction, the depth layers, and the caustics
// pass's lookup, so the tests evaluate exactly what the shaders do.
//
// Coordinates: a receiver's *entry coordinate* is where its flat-water refracted sun ray
// crosses the mean level (lightEntryCoord in the shaders). Under flat water the light entering
// the level at u lands on every receiver whose entry coordinate is u; waves move it by an offset
// that grows linearly with depth. One cascade alone is periodic on its tile, so the irradiance
// it makes at a given depth, indexed by entry coordinate, is periodic too: computed once per
// frame over one tile, it serves every receiver of the world and every view.
#ifndef POSTFX_SHARED_TILE_IRRADIANCE_H
#define POSTFX_SHARED_TILE_IRRADIANCE_H
#include "shared/common.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"

SHARED_BEGIN

SHARED_CONST int TILE_MAX_LAYERS = 8;
// Fixed-point scale of the scatter's integer accumulators: a flat-water texel sums to this.
// 2^32 / 2^20 = 4096 times flat water fits before a texel would wrap; the resolve clamps far
// below that (CausticsSettings::maxIrradiance <= 1e4 is clamped to kTileMaxIrradiance).
SHARED_CONST float TILE_FIXED_POINT = 1048576.0f;
SHARED_CONST float TILE_MAX_IRRADIANCE = 1024.0f;

// Depth of layer k of `layers` (m below the level): layers crowd toward the surface, where the
// pattern changes fastest with depth, as (k + 1)^1.5.
SHARED_FN float tileLayerDepth(int k, int layers, float maxDepth) {
  return maxDepth * pow(float(k + 1) / float(layers), 1.5f);
}

// Continuous layer coordinate of a receiver `depth` below the level: -1 at the surface (flat
// water's irradiance, 1), k at layer k, clamped to the deepest layer below it.
SHARED_FN float tileLayerCoord(float depth, int layers, float invMaxDepth) {
  float x = pow(clamp(depth * invMaxDepth, 0.0f, 1.0f), 2.0f / 3.0f);
  return float(layers) * x - 1.0f;
}

// Linear-interpolation weights of layers 4g..4g+3 at layer coordinate `coord`.
SHARED_FN vec4 tileLayerWeights(float coord, int group) {
  vec4 k = vec4(0.0f, 1.0f, 2.0f, 3.0f) + 4.0f * float(group);
  return max(vec4(1.0f) - abs(vec4(coord) - k), vec4(0.0f));
}

// Where the sun light through one cascade's surface point (slopes xy, height z) lands `depth`
// below the level, as an entry-coordinate offset from the point (m). flatDrift: the flat-water
// ray's horizontal travel per metre of depth (t0.xz / -t0.y).
SHARED_FN vec2 tileLandingOffset(vec3 surface, vec3 towardSun, float ior, vec2 flatDrift,
                                 float depth) {
  vec3 n = waterNormalFromSlopes(vec2(surface.x, surface.y));
  vec3 t = refract(-towardSun, n, 1.0f / ior);
  float h = sanitizeHeight(surface.z);
  // A ray that cannot go down carries no light (tileLandingFlux is 0); keep the offset finite.
  float down = max(-t.y, 1e-4f);
  return vec2(t.x, t.z) * ((depth + h) / down) - flatDrift * depth;
}

// tileLandingOffset to first order in the slopes, for the caustics pass (where the coarser
// cascades' offset is needed per pixel): depth * drift * slopes + height * flatDrift, `drift`
// the derivative of the landing offset per metre of depth with respect to the slopes at flat
// water, packed column-major (xx, zx, xz, zz). Off by the square of the slope: 1e-3 m per
// metre of depth at slope 0.1.
SHARED_FN vec2 tileLinearOffset(vec3 surface, vec4 drift, vec2 flatDrift, float depth) {
  vec2 s = sanitizeSlopes(vec2(surface.x, surface.y));
  vec2 perDepth = vec2(drift.x * s.x + drift.z * s.y, drift.y * s.x + drift.w * s.y);
  return perDepth * depth + flatDrift * sanitizeHeight(surface.z);
}

// The flux that surface point carries, per unit of level area, relative to flat water: the
// Fresnel transmittance ratio times the incoming beam's cross-section per unit area (the beam
// crosses the level at x - sunDrift h, whose Jacobian is 1 - sunDrift . slope). 0 on the back of
// a wave and for rays that cannot go down.
SHARED_FN float tileLandingFlux(vec3 surface, vec3 towardSun, float ior,
                                float invFlatTransmittance) {
  vec2 s = sanitizeSlopes(vec2(surface.x, surface.y));
  vec3 n = waterNormalFromSlopes(s);
  float c = dot(towardSun, n);
  vec3 t = refract(-towardSun, n, 1.0f / ior);
  if (!(c > 0.0f) || !(t.y < -1e-4f)) return 0.0f;
  vec2 sunDrift = vec2(towardSun.x, towardSun.z) / max(towardSun.y, 1e-6f);
  float beam = abs(1.0f - dot(sunDrift, s));
  return fresnelTransmittance(c, ior) * invFlatTransmittance * beam;
}

// Unresolved-slope spread (CausticsSettings::tileUnresolvedSpread). Each refracted point carries
// its cell's mean slope; the slopes inside the cell, and every finer cascade's (whose waves are
// far shorter than this cascade's pattern), deflect the light that cell sends by a further
// random offset that grows linearly with depth: to first order depth * J * s, J the landing
// drift per metre of depth and slope (tileLinearOffset's). Where those waves have focused and
// crossed (a few of their focal lengths down), the light they send is a diffuser's: the cascade's
// pattern arrives convolved with the offset's distribution, a Gaussian of covariance
//     C(depth) = depth^2 * J S J^T,
// S the covariance of the slopes the points do not resolve. The convolution runs over the
// periodic tile in the frequency domain (exact, any covariance, cost independent of its size).
// Cells per tile side whose slopes the spread's statistics sample (fewer where the tile has
// fewer points): 32^2 cells of a cascade's texels estimate its slope covariance within ~3 %.
SHARED_CONST int TILE_SPREAD_SAMPLE_CELLS = 32;
// Water texels per cell side the statistics read at most (a water texture much finer than the
// points is sampled on this sub-grid of each cell).
SHARED_CONST int TILE_SPREAD_MAX_CELL_TEXELS = 8;
// Workgroups per cascade of the statistics pass, each writing partial sums (CPU rasterisers run
// a workgroup on one thread).
SHARED_CONST int TILE_SPREAD_PARTS = 8;

// Landing-offset covariance per metre^2 of depth (xx, xz, zz), in the irradiance texels of a
// tile of `texelsPerMetre`, from slope covariance (xx, xz, zz) and the drift J (packed as
// tileLinearOffset takes it: column-major xx, zx, xz, zz).
SHARED_FN vec3 tileSpreadCovariance(vec3 slopeCovariance, vec4 drift, float texelsPerMetre) {
  // J S J^T with J = [[drift.x, drift.z], [drift.y, drift.w]] (rows: landing x, landing z).
  float a = drift.x, b = drift.z, c = drift.y, d = drift.w;
  float sxx = slopeCovariance.x, sxz = slopeCovariance.y, szz = slopeCovariance.z;
  float xx = a * a * sxx + 2.0f * a * b * sxz + b * b * szz;
  float xz = a * c * sxx + (a * d + b * c) * sxz + b * d * szz;
  float zz = c * c * sxx + 2.0f * c * d * sxz + d * d * szz;
  return vec3(xx, xz, zz) * (texelsPerMetre * texelsPerMetre);
}

SHARED_END

#endif
