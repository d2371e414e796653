// The wavefront area ratio's [4] irradiance lookup, shared by the caustics and the god rays:
// the depth-layered window texture the irradiance pass rendered this frame. Include after
// caustics_io.glsl, postfx/seabed_caustics/postfx_wavefront_area_ratio.h and
// irradiance_bspline.glsl.
#if POSTFX_WAVEFRONT_AREA_RATIO

layout(binding = POSTFX_UNIT_IRRADIANCE) uniform sampler2DArray causticIrradiance;

// Level 0 reconstructed with the cubic B-spline (irradiance_bspline.glsl).
float smoothLevelZero(vec2 uv, float layer, float texels) {
  BSplineTaps t = bsplineTaps(uv, texels);
  float e00 = textureLod(causticIrradiance, vec3(t.c0.x, t.c0.y, layer), 0.0).r;
  float e10 = textureLod(causticIrradiance, vec3(t.c1.x, t.c0.y, layer), 0.0).r;
  float e01 = textureLod(causticIrradiance, vec3(t.c0.x, t.c1.y, layer), 0.0).r;
  float e11 = textureLod(causticIrradiance, vec3(t.c1.x, t.c1.y, layer), 0.0).r;
  return bsplineSum(t, e00, e10, e01, e11);
}

// Layer k's irradiance at receiver p (camera-relative) `depthBelow` under the level, each
// layer looked up where ITS ray through the same surface point lands: the pattern is moved
// along the flat-water drift by the depth difference, so that the interpolation mixes the
// same caustic features at two stages of focus rather than two unrelated patterns.
// Filtered over the pixel's footprint (lod: log2 of its side in texels): irradiance is linear,
// so a far pixel gets the mean light over what it covers instead of one texel's sparkle; a
// pixel smaller than a texel gets the smooth B-spline reconstruction (blended in over the
// octave below one texel, so the change of filter leaves no line on screen).
float layerIrradiance(vec3 p, float depthBelow, float layer, float lod, float texels) {
  float layerDepth = packedLayerDepth(u.irradianceDepths[0], u.irradianceDepths[1], int(layer));
  vec2 xz = layerSamplePoint(p.xz, depthBelow, layerDepth, u.oblique.xy);
  vec2 uv = (xz - u.irradianceWindow.xy) * u.irradianceWindow.z;
  float filtered = textureLod(causticIrradiance, vec3(uv, layer), lod).r;
  float smoothing = clamp(-lod, 0.0, 1.0);
  // A dynamic branch: on GPUs the far pixels skip the four fetches (llvmpipe runs them masked).
  if (smoothing > 0.0) filtered = mix(filtered, smoothLevelZero(uv, layer, texels), smoothing);
  return filtered;
}

// Seed-004 irradiance at camera-relative p, depthBelow under the level, interpolated between
// the depth layers around it; `weight` is how much of it to use (0 outside the window).
float physicalIrradiance(vec3 p, float depthBelow, float logFootprint, out float weight) {
  weight = 0.0;
  int layers = int(u.irradianceWindow.w);
  if (layers <= 0) return 1.0;
  // The fade follows the camera continuously (p is camera-relative): the texture's window snaps
  // in steps of the coarsest mip texel, and a fade tied to it would jump with each step. Shrunk
  // by one such step, it stays inside the texture.
  vec2 uv = p.xz * u.irradianceWindow.z + 0.5;
  float texels = float(textureSize(causticIrradiance, 0).x);
  float margin = float(1 << IRRADIANCE_MIP_LEVELS) / texels;
  float edge = min(min(uv.x, uv.y), min(1.0 - uv.x, 1.0 - uv.y)) - margin;
  weight = smoothstep(0.0, IRRADIANCE_FADE_BAND, edge);
  if (!(weight > 0.0)) return 1.0;
  vec3 blend = layerBlend(depthBelow, u.irradianceDepths[0], u.irradianceDepths[1], layers);
  // Texels per metre: the texture's side over the window's.
  float lod = logFootprint + log2(texels * u.irradianceWindow.z);
  float lower = blend.x < 0.0 ? 1.0 : layerIrradiance(p, depthBelow, blend.x, lod, texels);
  float upper = layerIrradiance(p, depthBelow, blend.y, lod, texels);
  return mix(lower, upper, blend.z);
}
#endif
