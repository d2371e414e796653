#version 450 core
// Reflected caustics added into the host's HDR target above the water (postfx/reflected_caustics.h):
// albedo * E * intensity * R_flat * (the field's light on a face of normal n, flat water's
// n . l_r; reflectedReceiverLight), the field (reflected_field_pass.h: the sun's shadows on the
// water in it) interpolated between its height layers along the rays arriving at the receiver.
// Reads the seabed pass's block and G-buffer units (CausticsPass::bindState); compiled without
// the raw output (its framebuffer has the host's target only).
#include "postfx/seabed_caustics/caustics_io.glsl"
#include "shared/gbuffer_codec.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/water_sampling.glsl"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
#include "postfx/reflected_caustics/postfx_reflected_caustics.h"
#include "postfx/seabed_caustics/irradiance_bspline.glsl"

#if REFLECTED_VIEW_DEPTH
// ReflectedLanding::ViewDepth: the light the mirrored grid landed with on each view pixel
// (reflected_receiver_pass.h), in flat water's mirror light on the receiver.
// r: the window grid's light; g: the light times the variance per axis of where its rays land
// (m^2); b, a: the same for the outer grid.
layout(binding = POSTFX_UNIT_IRRADIANCE) uniform sampler2D receiverLight;
// Widest gather of the landing spread's blur (pixels each side).
const int kMaxBlur = 6;
#else
layout(binding = POSTFX_UNIT_IRRADIANCE) uniform sampler2DArray reflectedIrradiance;
#endif

// xy: camera-relative world xz of the window's centre (m); z: 1 / its side (1/m); w: height
// layers (channel c of layer k is texture layer c * layers + k)
layout(location = 0) uniform vec4 window;
layout(location = 1) uniform vec4 heights[2];  // layers 0-3 and 4-7 (m above the level)
// xyz: l_r, the flat mirror ray reversed (receiver -> water); w: maxHeight (m)
layout(location = 3) uniform vec4 towardWater;
// rgb: E_sun * intensity * R(theta_sun); w: 1 with the mirror mean, 0 for its modulation only
layout(location = 4) uniform vec4 mirrorLight;
layout(location = 5) uniform vec2 rise;  // -towardSun.xz / towardSun.y
layout(location = 6) uniform float maxLight;  // ReflectedCausticsSettings::maxIrradiance

// Flat water's field (1, rise) at this pixel, times the sun at its flat mirror point (with the
// shadow mask): what the pattern fades to beyond the window, below the lowest layer and above
// the highest, where the field's own shadows are not looked up. Set once per pixel by main().
vec3 meanField;

#if REFLECTED_VIEW_DEPTH
// The landed light at view pixel `local` (receiver p, normal n, `distance` from the camera),
// each grid's (window: x, outer: y) blurred by where the rays each grid ray stands for land
// about it (the sun's disc, the slopes finer than the grid: a Gaussian of the light-weighted
// variance around the pixel), gathered from the pixels of the same surface (within a few
// centimetres of its plane); the two added. One walk over the neighbours serves both grids.
float landedLight(ivec2 local, vec3 p, vec3 n, float distance) {
  ivec2 last = ivec2(u.viewport.zw) - 1;
  vec4 near = vec4(0.0);  // per grid: light, light times variance (rg window, ba outer)
  for (int y = -2; y <= 2; ++y)
    for (int x = -2; x <= 2; ++x)
      near += texelFetch(receiverLight, clamp(local + ivec2(x, y), ivec2(0), last), 0);
  vec4 c = texelFetch(receiverLight, local, 0);
  vec2 light = vec2(c.r, c.b);  // what a grid keeps when it gathers nothing around
  bvec2 lit = bvec2(near.x > 0.0, near.z > 0.0);
  light = mix(vec2(0.0), light, lit);
  float pixel = distance * u.depthAndWater.w;
  // What a pixel sees of the receiver is its footprint's average too: an area-matched disc of
  // radius pixel / sqrt(facing) has variance r^2 / 6 per axis (as the traced reference's kernel).
  float facing = max(abs(dot(n, p)) / max(distance, 1e-6), 1.0 / 16.0);
  vec2 sigma = sqrt(max(vec2(near.y / near.x, near.w / near.z), vec2(0.0)) +
                    pixel * pixel / (6.0 * facing));
  // The Gaussian, windowed to 0 at `radius` (2.5 sigma): taps enter and leave with no weight as
  // sigma changes, so the light does not jump when the spread grows a pixel.
  vec2 radius = 2.5 * sigma;
  ivec2 reach = clamp(ivec2(ceil(radius / max(pixel, 1e-9))), ivec2(0), ivec2(kMaxBlur));
  reach = mix(ivec2(0), reach, lit);  // an unlit grid gathers nothing
  int widest = max(reach.x, reach.y);
  if (widest == 0) return light.x + light.y;
  float tolerance = 0.02 + 0.01 * distance;
  vec2 sum = vec2(0.0), weights = vec2(0.0);
  for (int y = -kMaxBlur; y <= kMaxBlur; ++y) {
    if (abs(y) > widest) continue;
    for (int x = -kMaxBlur; x <= kMaxBlur; ++x) {
      if (abs(x) > widest) continue;
      ivec2 j = local + ivec2(x, y);
      if (any(lessThan(j, ivec2(0))) || any(greaterThan(j, last))) continue;
      float depth = texelFetch(gbufferDepth, j + ivec2(u.viewOrigin.xy), 0).r;
      if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) continue;
      vec3 q = mat3(u.viewToWorld) *
               viewPositionFromDepth((vec2(j) + 0.5) * u.viewport.xy, depth, u.projection,
                                     u.depthAndWater.xy, POSTFX_DEPTH_CONVENTION);
      if (!(abs(dot(q - p, n)) < tolerance)) continue;
      vec3 d = q - p;
      vec4 v = texelFetch(receiverLight, j, 0);
      vec2 value = vec2(v.r, v.b);
      for (int g = 0; g < 2; ++g) {
        if (abs(x) > reach[g] || abs(y) > reach[g]) continue;
        float window = max(1.0 - dot(d, d) / (radius[g] * radius[g]), 0.0);
        float w = exp(-dot(d, d) / (2.0 * sigma[g] * sigma[g])) * window * window;
        sum[g] += w * value[g];
        weights[g] += w;
      }
    }
  }
  for (int g = 0; g < 2; ++g)
    if (reach[g] > 0 && weights[g] > 0.0) light[g] = sum[g] / weights[g];
  return light.x + light.y;
}
#endif

#if !REFLECTED_VIEW_DEPTH
float smoothLevelZero(vec2 uv, float layer, float texels) {
  BSplineTaps t = bsplineTaps(uv, texels);
  float e00 = textureLod(reflectedIrradiance, vec3(t.c0.x, t.c0.y, layer), 0.0).r;
  float e10 = textureLod(reflectedIrradiance, vec3(t.c1.x, t.c0.y, layer), 0.0).r;
  float e01 = textureLod(reflectedIrradiance, vec3(t.c0.x, t.c1.y, layer), 0.0).r;
  float e11 = textureLod(reflectedIrradiance, vec3(t.c1.x, t.c1.y, layer), 0.0).r;
  return bsplineSum(t, e00, e10, e01, e11);
}

// Channel layer `layer` at uv, filtered over the pixel's footprint (lod).
float channelAt(vec2 uv, float layer, float lod, float texels) {
  float filtered = textureLod(reflectedIrradiance, vec3(uv, layer), lod).r;
  float smoothing = clamp(-lod, 0.0, 1.0);
  if (smoothing > 0.0) filtered = mix(filtered, smoothLevelZero(uv, layer, texels), smoothing);
  return filtered;
}


// Layer k's field (light, drift sums) at camera-relative xz `point`, faded to meanField toward
// the window's edge (the window snaps in steps of its coarsest filtered texel; the fade follows
// the camera and stays inside). `axis`: the pixel's footprint's long half-axis in the layer (m),
// averaged over by up to four taps along it.
vec3 layerField(vec2 point, int k, int layers, float lod, float texels, vec2 axis) {
  vec2 uv = (point - window.xy) * window.z + 0.5;
  float margin = float(1 << IRRADIANCE_MIP_LEVELS) / texels;
  float edge = min(min(uv.x, uv.y), min(1.0 - uv.x, 1.0 - uv.y)) - margin;
  float weight = smoothstep(0.0, IRRADIANCE_FADE_BAND, edge);
  if (!(weight > 0.0)) return meanField;
  vec2 axisUv = axis * window.z;
  int taps = clamp(int(ceil(2.0 * length(axisUv) * texels * exp2(-max(lod, 0.0)))), 1, 4);
  vec3 f = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    if (i >= taps) break;
    vec2 at = uv + axisUv * ((2.0 * float(i) + 1.0) / float(taps) - 1.0);
    f += vec3(channelAt(at, float(k), lod, texels), channelAt(at, float(layers + k), lod, texels),
              channelAt(at, float(2 * layers + k), lod, texels));
  }
  return mix(meanField, f / float(taps), weight);
}

// Layer k's field for a receiver at xz, `height` above the level: where the rays arriving there
// crossed the layer. First where the flat mirror ray crosses it, then where the mean ray found
// there does: between layers the pattern travels with its rays, which low waves tilt far from
// the flat ray (a blend of two layers along it smeared the lines between them).
vec3 layerLight(vec2 xz, float height, int k, int layers, float lod, float texels, vec2 axis) {
  float layerHeight = packedLayerDepth(heights[0], heights[1], k);
  vec2 first = reflectedLayerSamplePoint(xz, height, layerHeight, rise);
  vec2 drift = reflectedMeanDrift(layerField(first, k, layers, lod, texels, axis), rise);
  vec2 along = reflectedLayerSamplePoint(xz, height, layerHeight, drift);
  return layerField(along, k, layers, lod, texels, axis);
}

#endif

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) {
    emitNothing();
    return;
  }
  vec3 viewPos = viewPositionFromDepth((gl_FragCoord.xy - u.viewOrigin.xy) * u.viewport.xy, depth,
                                       u.projection, u.depthAndWater.xy, POSTFX_DEPTH_CONVENTION);
  vec3 p = mat3(u.viewToWorld) * viewPos;  // camera-relative world position
  float height = p.y - u.depthAndWater.z;
  if (!(height > 0.0)) {  // at or under the water (or NaN from a broken depth texel)
    emitNothing();
    return;
  }
  vec3 n = decodeNormal(texelFetch(gbufferNormal, pixel, 0), POSTFX_NORMAL_ENCODING);
  // Whatever its facing: a face turned from flat water's mirror ray still meets the rays the
  // waves tilt toward it (none reaches a face from behind: its light is clamped at 0).
  if (!(dot(n, n) > 0.5)) {  // a zero or NaN G-buffer normal
    emitNothing();
    return;
  }
  float distance = length(viewPos);
  float flatVisibility = 1.0;
  vec3 water = p + towardWater.xyz * (height / max(-towardWater.y, 1e-6));
#if POSTFX_SHADOW_MASK
  flatVisibility = sunVisibility(water, vec3(0.0, 1.0, 0.0));
#endif
  meanField = vec3(1.0, rise) * flatVisibility;
  float keep = reflectedTopWeight(height, towardWater.w);
  // Without the mirror mean the host's own flat mirror light is taken off: where the sun is
  // shaded at flat water's mirror point, the host's light holds none of it.
  float subtract = (1.0 - mirrorLight.w) * flatVisibility;
#if REFLECTED_VIEW_DEPTH
  // The landed light where the flat mirror point lies in the window (its pattern whole), the
  // mean beyond it and above the followed height.
  vec2 mirrorUv = (water.xz - window.xy) * window.z + 0.5;
  float edge = min(min(mirrorUv.x, mirrorUv.y), min(1.0 - mirrorUv.x, 1.0 - mirrorUv.y));
  float inside = smoothstep(0.0, IRRADIANCE_FADE_BAND, edge) * keep;
  ivec2 local = pixel - ivec2(u.viewOrigin.xy);
  float landed = landedLight(local, p, n, distance);
  float mean = reflectedReceiverLight(n, meanField, -towardWater.y, rise, 0.0, maxLight);
  float flatLight = max(dot(n, towardWater.xyz), 0.0);
  float light = mix(mean, min(landed, maxLight), inside) - subtract * flatLight;
#else
  float texels = float(textureSize(reflectedIrradiance, 0).x);
  // The pixel's footprint as the layers see it: carried along the mirror ray onto a horizontal
  // plane, a step up a wall moves the lookup by `rise` (2.7 m per metre for a sun 20 degrees
  // up), so a wall's footprint stretches that much along it: the wall's pattern is the layer's
  // squeezed, and a lookup filtered for the footprint alone aliased into speckle. Filtered for
  // the footprint across, averaged along (anisotropically, as the trace's kernel on the wall).
  float footprint = surfaceLogFootprint(n, p, distance);
  float lod = footprint + log2(texels * window.z);
  vec3 slope = vec3(0.0, 1.0, 0.0) - n * n.y;  // up the face
  float slopeLength = length(slope);
  vec2 axis = vec2(0.0);
  float halfFootprint = 0.5 * exp2(footprint);
  if (slopeLength > 1e-3) axis = (slope.xz - rise * slope.y) * (halfFootprint / slopeLength);
  int layers = int(window.w);
  vec3 blend = layerBlend(height, heights[0], heights[1], layers);
  vec3 lower = meanField;
  if (!(blend.x < 0.0)) lower = layerLight(p.xz, height, int(blend.x), layers, lod, texels, axis);
  vec3 upper = layerLight(p.xz, height, int(blend.y), layers, lod, texels, axis);
  vec3 field = mix(meanField, mix(lower, upper, blend.z), keep);
  float light = reflectedReceiverLight(n, field, -towardWater.y, rise, subtract, maxLight);
#endif
  vec3 albedo = sanitizeAlbedo(texelFetch(gbufferAlbedo, pixel, 0).rgb);
  // ViewExtinction::Plugin: the part of the view ray under the water, from a camera under the
  // level looking up at a hull (the ray is straight: the ratio of the heights); none from above.
  float cameraDepth = u.depthAndWater.z;
  float viewLength = cameraDepth > 0.0 ? distance * cameraDepth / (cameraDepth + height) : 0.0;
  outLight = vec4(albedo * mirrorLight.rgb * light * exp(-u.viewExtinction.rgb * viewLength), 0.0);
}
