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

// The cascades worth sampling at one point: each one's weight, computed once for every
// projection, and the first and last with a weight as a loop range. A range rather than a skip
// inside the loop because SIMD rasterisers (llvmpipe) run both sides of a branch for a group of
// pixels but leave a loop as soon as every pixel of the group is done: only a shorter loop saves
// the fetches there. On GPUs either form branches per warp.
struct CascadeSelection {
  ivec2 range;  // first, last; empty (first > last) when none has a weight
  vec4 weight;  // per cascade
};

CascadeSelection selectCascades(float depthBelow, float logFootprint) {
  CascadeSelection selection = CascadeSelection(ivec2(POSTFX_MAX_CASCADES, -1), vec4(0.0));
  int cascades = int(u.oblique.w);
  for (int c = 0; c < POSTFX_MAX_CASCADES; ++c) {
    if (c >= cascades) break;
    float weight = cascadeWeight(c, depthBelow, logFootprint);
    selection.weight[c] = weight;
    if (weight > 0.0) selection.range = ivec2(min(selection.range.x, c), c);
  }
  return selection;
}

// No cascade: nothing is fetched.
const CascadeSelection kNoCascades = CascadeSelection(ivec2(1, 0), vec4(0.0));

// Sum of the selected cascades' slopes for one projection, each cascade at its own mip level
// so that small tiles blur away with distance and stop showing their repetition.
vec2 cascadeSlopes(vec2 coordMetres, int plane, float logFootprint, CascadeSelection selection) {
  vec2 slopes = vec2(0.0);
  for (int c = selection.range.x; c <= selection.range.y; ++c) {
    vec4 axes = u.cascadeAxes[c];
    // The camera's share of the coordinate was reduced modulo the tile in double on the CPU.
    vec2 offset = plane == 1 ? u.cascadeOblique[c].xy : (plane == 0 ? axes.zy : axes.xy);
    vec2 uv = offset + coordMetres * axes.w;
    float lod = logFootprint + u.cascadeOblique[c].z;
    slopes += selection.weight[c] * textureLod(waterSurface, WATER_COORD(uv, c), lod).rg;
  }
  return slopes;
}

#if POSTFX_SHADOW_MASK
float sunVisibility(vec3 p) {
  vec4 clip = u.shadowMatrix * vec4(p, 1.0);
  if (!(clip.w > 0.0)) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  if (!(abs(ndc.x) <= 1.0 && abs(ndc.y) <= 1.0)) return 1.0;  // outside the map: lit
  float ref = (u.shadowParams.y > 0.5 ? ndc.z * 0.5 + 0.5 : ndc.z) + u.shadowParams.x;
  return texture(sunShadowMap, vec3(ndc.xy * 0.5 + 0.5, clamp(ref, 0.0, 1.0)));
}
#endif
