// Water-texture and shadow-map lookups shared by the caustics and god-ray passes (include after
// caustics_io.glsl): one body, so the god rays see exactly the caustics' light pattern.

// How much of cascade c a point `depthBelow` metres under the level, seen with a footprint of
// 2^logFootprint metres, can show: 0 where the cascade's waves cannot focus light at that depth
// yet (their first-order irradiance modulation is below the contrast cut-off; they only tilt
// it) or are all finer than the footprint. Skipping those saves a filtered fetch each.
float cascadeWeight(int c, float depthBelow, float logFootprint) {
  vec4 skip = u.cascadeSkip[c];
  if (logFootprint >= skip.y) return 0.0;
  float cut = u.lightScale.w;
  if (skip.x < 0.0 || cut <= 0.0) return 1.0;
  return smoothstep(cut, 2.0 * cut, depthBelow * skip.x);
}

// Each cascade's weight at one point (0: not sampled), computed once for every projection.
vec4 selectCascades(float depthBelow, float logFootprint) {
  vec4 weight = vec4(0.0);
  int cascades = int(u.oblique.w);
  for (int c = 0; c < POSTFX_CASCADE_SLOTS; ++c) {  // unrolled: constant bound
    if (c < cascades) weight[c] = cascadeWeight(c, depthBelow, logFootprint);
  }
  return weight;
}

// No cascade: nothing is fetched.
const vec4 kNoCascades = vec4(0.0);

// Where the light that reaches camera-relative p entered the water: p moved along the refracted
// sun to the water plane, in the oblique (x, z) coordinates the cascades' offsets are kept in.
vec2 lightEntryCoord(vec3 p) {
  return vec2(p.x - u.oblique.x * p.y, p.z - u.oblique.y * p.y);
}

// Cascade c's slopes for one projection (plane: 0 world x, 1 along the light, 2 world z), at its
// own mip level so that small tiles blur away with distance and stop showing their repetition.
// Called with constant c and plane only, so every index below folds to a constant: no per-pixel
// indexing (scratch memory on GPUs, one scalar load per pixel on SIMD CPUs) and no loop (both
// cost llvmpipe more than the fetches themselves: a loop over a per-pixel cascade range measured
// 2.27x the floor at 1280x720, the same fetches written out 1.74x).
vec2 cascadeSlope(int c, int plane, vec2 coordMetres, float logFootprint, float weight) {
  vec2 slope = vec2(0.0);
  if (weight > 0.0) {  // GPUs skip the fetch per warp; CPU rasterisers run it masked
    vec4 axes = u.cascadeAxes[c];
    // The camera's share of the coordinate was reduced modulo the tile in double on the CPU.
    vec2 offset = plane == 1 ? u.cascadeOblique[c].xy : (plane == 0 ? axes.zy : axes.xy);
    vec2 uv = offset + coordMetres * axes.w;
    float lod = logFootprint + u.cascadeOblique[c].z;
    slope = weight * textureLod(waterSurface, WATER_COORD(uv, c), lod).rg;
  }
  return slope;
}

// Sum of the weighted cascades' slopes for one projection; one lookup per cascade slot the
// context was created with (CreateDesc::maxWaterCascades).
vec2 cascadeSlopes(vec2 coordMetres, int plane, float logFootprint, vec4 weight) {
  vec2 slopes = cascadeSlope(0, plane, coordMetres, logFootprint, weight.x);
#if POSTFX_CASCADE_SLOTS > 1
  slopes += cascadeSlope(1, plane, coordMetres, logFootprint, weight.y);
#endif
#if POSTFX_CASCADE_SLOTS > 2
  slopes += cascadeSlope(2, plane, coordMetres, logFootprint, weight.z);
#endif
#if POSTFX_CASCADE_SLOTS > 3
  slopes += cascadeSlope(3, plane, coordMetres, logFootprint, weight.w);
#endif
  return slopes;
}

#if POSTFX_SHADOW_MASK
#include "postfx/seabed_caustics/sun_visibility.glsl"
#endif
