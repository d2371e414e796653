#version 450 core
// The water surface seen from above (Fresnel mix of sky reflection and the fogged scene below,
// through blending) and from below (Snell's window; total internal reflection outside it).
#include "shared/gbuffer_codec.h"
#include "shared/sample_frame.h"
#include "shared/sample_optics.h"
#include "sample/reconstruct.glsl"
#include "sample/water_column.glsl"
#include "sample/local_water.glsl"
in vec2 surfaceXZ;
in vec3 relativePosition;
layout(binding = 0) uniform sampler2D depthTexture;
layout(binding = 1) uniform sampler2D sceneBelow;  // the fogged frame before the surface pass
layout(binding = 5) uniform sampler2DArray slopes;
out vec4 outColor;  // blended as rgb + destination * (1 - a)

// Screen-space refraction: bend the view ray at the surface, walk it as far as the scene behind
// this pixel lies, and read the frame where that point projects. A sample that lands on
// something in front of the water (or off screen) falls back to the straight-through pixel.
// The walk is capped at 3 m: screen-space refraction has no data for the true, longer path
// and a longer walk only smears.
vec3 refractedScene(vec3 view, vec3 n, float ior) {
  vec2 size = vec2(textureSize(sceneBelow, 0));
  vec2 uv = gl_FragCoord.xy / size;
  vec3 straight = texture(sceneBelow, uv).rgb;
  float depth = texelFetch(depthTexture, ivec2(gl_FragCoord.xy), 0).r;
  float behind = isSkyDepth(depth, int(projectionZ.z))
                     ? 3.0
                     : max(length(reconstructRelative(uv, depth)) - length(relativePosition), 0.0);
  vec3 bent = refract(view, n, 1.0 / ior);
  vec4 clip = viewProjection * vec4(relativePosition + bent * min(behind, 3.0), 1.0);
  if (!(clip.w > 0.0)) return straight;
  vec2 bentUv = clip.xy / clip.w * 0.5 + 0.5;
  if (any(lessThan(bentUv, vec2(0.0))) || any(greaterThan(bentUv, vec2(1.0)))) return straight;
  float bentDepth = texelFetch(depthTexture, ivec2(bentUv * size), 0).r;
  if (!isSkyDepth(bentDepth, int(projectionZ.z)) &&
      cameraHeight.x + reconstructRelative(bentUv, bentDepth).y > 0.0) {
    return straight;  // the bent ray found something above the water: not what lies below
  }
  return texture(sceneBelow, bentUv).rgb;
}

vec3 surfaceNormal() {
  vec2 slope = vec2(0.0);
  vec2 uv;
  bool local = localWaterUv(surfaceXZ, uv);
  if (local) slope = localWaterSlope(uv);
  int count = local && localWaterMode() == kLocalWaterReplace ? 0 : int(cascadeInfo.x);
  for (int c = 0; c < count; ++c) {
    slope += texture(slopes, vec3(surfaceXZ * cascadeTile[c].y + cascadeTile[c].zw, float(c))).xy;
  }
  return normalize(vec3(-slope.x, 1.0, -slope.y));
}

void main() {
  vec3 n = surfaceNormal();
  vec3 view = normalize(relativePosition);  // camera -> surface
  float ior = waterParams.x;
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  vec3 deepColor = deepWaterColour();
  // Which side we look from is the camera's side of the water, not the triangle's facing: from
  // below, the back of a far crest faces us and must still read as seen from below.
  if (cameraHeight.x >= 0.0) {
    // From above: Fresnel mix of the reflected sky and the refracted (already fogged) scene.
    vec3 r = reflect(view, n);
    r.y = abs(r.y);  // a grazing reflection into a wave's back still sees sky, not the seabed
    float f = fresnelReflectance(max(-dot(view, n), 0.0), 1.0, ior);
    vec3 below = refractedScene(view, n, ior);
    outColor = vec4(skyRadiance(normalize(r), sunDirection.xyz) * f + below * (1.0 - f), 1.0);
    return;
  }
  // From below: the surface normal faces away from us. Outside Snell's window F = 1 (total
  // internal reflection) and we see the deep water reflected.
  vec3 color = belowSurfaceRadiance(view, -n, sunDirection.xyz, deepColor);
  vec3 transmittance = exp(-sigmaT * length(relativePosition));
  // The fog pass already wrote deepColor (plus any light the plugin added in the water column)
  // here: add only the difference the surface makes, so that added light survives.
  outColor = vec4(transmittance * (color - deepColor), 0.0);
}
