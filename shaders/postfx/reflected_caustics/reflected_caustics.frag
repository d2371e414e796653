#version 450 core
// Reflected caustics added into the host's HDR target above the water (postfx/reflected_caustics.h):
// albedo * E * intensity * R_flat * I * max(n . l_r, 0) * visibility, I the reflected light field
// (reflected_field_pass.h) interpolated between its height layers along the flat mirror ray.
// Reads the seabed pass's block and G-buffer units (CausticsPass::bindState); compiled without
// the raw output (its framebuffer has the host's target only).
#include "postfx/seabed_caustics/caustics_io.glsl"
#include "shared/gbuffer_codec.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/water_sampling.glsl"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
#include "postfx/reflected_caustics/postfx_reflected_caustics.h"
#include "postfx/seabed_caustics/irradiance_bspline.glsl"

layout(binding = POSTFX_UNIT_IRRADIANCE) uniform sampler2DArray reflectedIrradiance;

// xy: camera-relative world xz of the window's centre (m); z: 1 / its side (1/m); w: layers
layout(location = 0) uniform vec4 window;
layout(location = 1) uniform vec4 heights[2];  // layers 0-3 and 4-7 (m above the level)
// xyz: l_r, the flat mirror ray reversed (receiver -> water); w: maxHeight (m)
layout(location = 3) uniform vec4 towardWater;
// rgb: E_sun * intensity * R(theta_sun); w: 1 with the mirror mean, 0 for its modulation only
layout(location = 4) uniform vec4 mirrorLight;
layout(location = 5) uniform vec2 rise;  // -towardSun.xz / towardSun.y

float smoothLevelZero(vec2 uv, float layer, float texels) {
  BSplineTaps t = bsplineTaps(uv, texels);
  float e00 = textureLod(reflectedIrradiance, vec3(t.c0.x, t.c0.y, layer), 0.0).r;
  float e10 = textureLod(reflectedIrradiance, vec3(t.c1.x, t.c0.y, layer), 0.0).r;
  float e01 = textureLod(reflectedIrradiance, vec3(t.c0.x, t.c1.y, layer), 0.0).r;
  float e11 = textureLod(reflectedIrradiance, vec3(t.c1.x, t.c1.y, layer), 0.0).r;
  return bsplineSum(t, e00, e10, e01, e11);
}

// Layer k's light for a receiver at camera-relative xz, `height` above the level: looked up where
// the flat mirror ray through it crosses the layer, filtered over the pixel's footprint (lod),
// faded to the flat mean 1 toward the window's edge (the window snaps in steps of its coarsest
// filtered texel; the fade follows the camera and stays inside).
float layerLight(vec2 xz, float height, int k, float lod, float texels) {
  float layerHeight = packedLayerDepth(heights[0], heights[1], k);
  vec2 uv = (reflectedLayerSamplePoint(xz, height, layerHeight, rise) - window.xy) * window.z + 0.5;
  float margin = float(1 << IRRADIANCE_MIP_LEVELS) / texels;
  float edge = min(min(uv.x, uv.y), min(1.0 - uv.x, 1.0 - uv.y)) - margin;
  float weight = smoothstep(0.0, IRRADIANCE_FADE_BAND, edge);
  if (!(weight > 0.0)) return 1.0;
  float layer = float(k);
  float filtered = textureLod(reflectedIrradiance, vec3(uv, layer), lod).r;
  float smoothing = clamp(-lod, 0.0, 1.0);
  if (smoothing > 0.0) filtered = mix(filtered, smoothLevelZero(uv, layer, texels), smoothing);
  return mix(1.0, filtered, weight);
}

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
  float nDotL = dot(n, towardWater.xyz);  // 0 for a zero/NaN G-buffer normal
  if (!(nDotL > 0.0)) {
    emitNothing();
    return;
  }
  float visibility = 1.0;
#if POSTFX_SHADOW_MASK
  // The sun at the water this receiver's light was mirrored by (flat water's point): none
  // reaches the water in the shade of a pier or hull, which then mirrors nothing.
  vec3 water = p + towardWater.xyz * (height / max(-towardWater.y, 1e-6));
  visibility = sunVisibility(water, vec3(0.0, 1.0, 0.0));
  if (!(visibility > 0.0)) {
    emitNothing();
    return;
  }
#endif
  float distance = length(viewPos);
  float texels = float(textureSize(reflectedIrradiance, 0).x);
  float lod = surfaceLogFootprint(n, p, distance) + log2(texels * window.z);
  int layers = int(window.w);
  vec3 blend = layerBlend(height, heights[0], heights[1], layers);
  float lower = blend.x < 0.0 ? 1.0 : layerLight(p.xz, height, int(blend.x), lod, texels);
  float upper = layerLight(p.xz, height, int(blend.y), lod, texels);
  float irradiance = mix(1.0, mix(lower, upper, blend.z), reflectedTopWeight(height, towardWater.w));
  float light = (irradiance - (1.0 - mirrorLight.w)) * nDotL * visibility;
  vec3 albedo = sanitizeAlbedo(texelFetch(gbufferAlbedo, pixel, 0).rgb);
  // ViewExtinction::Plugin: the part of the view ray under the water, from a camera under the
  // level looking up at a hull (the ray is straight: the ratio of the heights); none from above.
  float cameraDepth = u.depthAndWater.z;
  float viewLength = cameraDepth > 0.0 ? distance * cameraDepth / (cameraDepth + height) : 0.0;
  outLight = vec4(albedo * mirrorLight.rgb * light * exp(-u.viewExtinction.rgb * viewLength), 0.0);
}
