// The local water regions' light (Feature::LocalWater), shared by the caustics and the god rays:
// each region's depth-layered irradiance (its pre-pass, local_water_vertices.comp and the
// wavefront area ratio's draws) blended over the periodic light a receiver would get. Include
// after caustics_io.glsl, postfx_wavefront_area_ratio.h, postfx_local_water.h and
// irradiance_bspline.glsl.
#if POSTFX_LOCAL_WATER

// Region r's layers: [0, layers) its own light (Add: with the cascades beneath), Add mode's
// [layers, 2 layers) the same grid without the region's heights. Units
// POSTFX_UNIT_LOCAL_WATER + r.
layout(binding = POSTFX_UNIT_LOCAL_WATER) uniform sampler2DArray localIrradiance[POSTFX_MAX_LOCAL_WATER];

// One fetch of region r's layers: constant indices into the sampler array (r is dynamically
// uniform, but a constant is what every compiler takes).
float localFetch(int r, vec3 coord, float lod) {
  if (r == 0) return textureLod(localIrradiance[0], coord, lod).r;
  if (r == 1) return textureLod(localIrradiance[1], coord, lod).r;
  if (r == 2) return textureLod(localIrradiance[2], coord, lod).r;
  return textureLod(localIrradiance[3], coord, lod).r;
}

// Layer `layer` of region r at texture coordinate uv: filtered over the footprint (lod, in
// texels), the B-spline below one texel (as the window model's lookup).
float localLayer(int r, vec2 uv, float layer, float lod, float texels) {
  float filtered = localFetch(r, vec3(uv, layer), lod);
  float smoothing = clamp(-lod, 0.0, 1.0);
  if (smoothing > 0.0) {
    BSplineTaps t = bsplineTaps(uv, texels);
    float e00 = localFetch(r, vec3(t.c0.x, t.c0.y, layer), 0.0);
    float e10 = localFetch(r, vec3(t.c1.x, t.c0.y, layer), 0.0);
    float e01 = localFetch(r, vec3(t.c0.x, t.c1.y, layer), 0.0);
    float e11 = localFetch(r, vec3(t.c1.x, t.c1.y, layer), 0.0);
    filtered = mix(filtered, bsplineSum(t, e00, e10, e01, e11), smoothing);
  }
  return filtered;
}

// One field of region r (first layer `base`) at depth `depthBelow`, interpolated between the
// layers around it (1 at the surface). Every layer is indexed by the entry point: each one's
// window lies where flat water's light from the same surface lands at its depth.
float localField(int r, vec2 uv, float depthBelow, float base, float lod, float texels) {
  int layers = int(lw.drift[r].z);
  vec3 blend = layerBlend(depthBelow, lw.depths[2 * r], lw.depths[2 * r + 1], layers);
  float lower = blend.x < 0.0 ? 1.0 : localLayer(r, uv, base + blend.x, lod, texels);
  float upper = localLayer(r, uv, base + blend.y, lod, texels);
  return mix(lower, upper, blend.z);
}

// The light at camera-relative p, depthBelow under the level, given what the periodic water
// gives there (per channel: dispersion's three; the regions' own light is one, refracted with
// the mean IOR): each region in turn (a later one over an earlier one where they overlap).
vec3 localWaterIrradiance(vec3 p, float depthBelow, float logFootprint, vec3 periodic) {
  vec3 light = periodic;
  for (int r = 0; r < POSTFX_MAX_LOCAL_WATER; ++r) {
    if (float(r) >= lw.count.x) break;
    vec2 entry = localWaterEntry(p.xz, depthBelow, lw.frame[r], lw.drift[r]);
    float weight = localWaterWeight(entry, lw.extent[r]);
    // A dynamic branch: on GPUs pixels outside every region skip the fetches.
    if (!(weight > 0.0)) continue;
    vec2 uv = (entry - lw.window[r].xy) * lw.window[r].zw;
    float lod = logFootprint + lw.drift[r].w;
    bool replace = lw.extent[r].w > 0.5;
    float layers = lw.drift[r].z;
    float texels = lw.texels[r];
    float joint = localField(r, uv, depthBelow, 0.0, lod, texels);
    float seaOnly = replace ? 0.0 : localField(r, uv, depthBelow, layers, lod, texels);
    float mode = replace ? 1.0 : 0.0;
    light = vec3(localWaterLight(light.r, joint, seaOnly, weight, mode),
                 localWaterLight(light.g, joint, seaOnly, weight, mode),
                 localWaterLight(light.b, joint, seaOnly, weight, mode));
  }
  return light;
}
#endif
