// The local water regions' light (Feature::LocalWater), shared by the caustics and the god rays:
// each region's depth-layered irradiance (its pre-pass, local_water_vertices.comp and the
// wavefront area ratio's draws) blended over the periodic light a receiver would get. Include
// after caustics_io.glsl, postfx_wavefront_area_ratio.h, postfx_local_water.h and
// irradiance_bspline.glsl.
#if POSTFX_LOCAL_WATER

// Every region's layers in one texture (a sampler array indexed per region cost llvmpipe twice
// the caustics pass: it ran every arm): region r's [0, layers) its own light (Add: with the
// cascades beneath), Add mode's [layers, 2 layers) the same grid without the region's heights,
// from its first layer lw.lookup[r].x, in the corner [0, lw.lookup[r].y) of each.
layout(binding = POSTFX_UNIT_LOCAL_WATER) uniform sampler2DArray localIrradiance;

// Layer `layer` at texture coordinate uv: filtered over the footprint (lod, in texels), the
// B-spline below one texel (as the window model's lookup). `texels`: the texture's side.
float localLayer(vec2 uv, float layer, float lod, float texels) {
  float filtered = textureLod(localIrradiance, vec3(uv, layer), lod).r;
  float smoothing = clamp(-lod, 0.0, 1.0);
  if (smoothing > 0.0) {
    BSplineTaps t = bsplineTaps(uv, texels);
    float e00 = textureLod(localIrradiance, vec3(t.c0.x, t.c0.y, layer), 0.0).r;
    float e10 = textureLod(localIrradiance, vec3(t.c1.x, t.c0.y, layer), 0.0).r;
    float e01 = textureLod(localIrradiance, vec3(t.c0.x, t.c1.y, layer), 0.0).r;
    float e11 = textureLod(localIrradiance, vec3(t.c1.x, t.c1.y, layer), 0.0).r;
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
  float lower = blend.x < 0.0 ? 1.0 : localLayer(uv, base + blend.x, lod, texels);
  float upper = localLayer(uv, base + blend.y, lod, texels);
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
    vec2 uv = (entry - lw.window[r].xy) * lw.window[r].zw * lw.lookup[r].y;
    float lod = logFootprint + lw.drift[r].w;
    bool replace = lw.extent[r].w > 0.5;
    float layers = lw.drift[r].z;
    float texels = lw.lookup[r].z, base = lw.lookup[r].x;
    float joint = localField(r, uv, depthBelow, base, lod, texels);
    float seaOnly = replace ? 0.0 : localField(r, uv, depthBelow, base + layers, lod, texels);
    float mode = replace ? 1.0 : 0.0;
    light = vec3(localWaterLight(light.r, joint, seaOnly, weight, mode),
                 localWaterLight(light.g, joint, seaOnly, weight, mode),
                 localWaterLight(light.b, joint, seaOnly, weight, mode));
  }
  return light;
}
#endif
