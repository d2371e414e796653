#version 450 core
// Deferred lighting: the sun above the water (shadowed; below it the plugin's caustics are the
// sun), point and spot lights (inverse square, cone, extinction along their path under water,
// shadowed) and sky ambient.
// No fog here: the composite pass fogs this light, then the plugin adds its own (attenuated).
#include "shared/gbuffer_codec.h"
#include "shared/sample_frame.h"
#include "shared/sample_lights.h"
#include "shared/sample_optics.h"
#include "sample/reconstruct.glsl"
#include "sample/sun_shadow.glsl"
in vec2 uv;
layout(binding = 0) uniform sampler2D depthTexture;
layout(binding = 1) uniform sampler2D normalTexture;
layout(binding = 2) uniform sampler2D albedoTexture;
layout(binding = 3) uniform sampler2DShadow shadowMap;
layout(binding = 4) uniform sampler2DShadow lightShadowMaps[SAMPLE_MAX_LIGHTS];
out vec4 outRadiance;

// Lit share of light i at `relative` (camera-relative), 1 outside its shadow map's view.
float lightShadow(int i, vec3 relative, vec3 normal, vec3 toLight, float distance) {
  // Normal offset by about a texel at this distance, as the sun's.
  float texel = lightCone[i].z * distance;
  vec3 biased = relative + normal * texel * 1.5 + toLight * texel;
  vec4 clip = lightViewProjection[i] * vec4(biased, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 coord = clip.xyz / clip.w;
  coord.xy = coord.xy * 0.5 + 0.5;
  if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0)))) return 1.0;
  vec2 texelStep = 1.0 / vec2(textureSize(lightShadowMaps[i], 0));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(lightShadowMaps[i], vec3(coord.xy + vec2(x, y) * texelStep, coord.z));
  return lit / 9.0;
}

// Irradiance from the point and spot lights at a surface `height` m above the water.
vec3 localLights(vec3 relative, vec3 normal, float height, vec3 sigmaT) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < int(lightCount.x); ++i) {
    vec3 toLight = lightPosition[i].xyz - relative;
    float distance = max(length(toLight), 1e-3);
    toLight /= distance;
    float cosine = dot(normal, toLight);
    if (cosine <= 0.0) continue;
    float cone = 1.0;
    if (lightPosition[i].w > 0.5) {
      float angle = acos(clamp(dot(-toLight, lightAxis[i].xyz), -1.0, 1.0));
      float halfAngle = lightCone[i].x, fadeStart = lightCone[i].y;
      cone = fadeStart < halfAngle ? 1.0 - smoothstep(fadeStart, halfAngle, angle)
                                  : float(angle < halfAngle);
    }
    if (cone <= 0.0) continue;
    // The part of the straight path below the water (no refraction at the surface).
    float lightHeight = lightIntensity[i].w;
    float below = distance;
    if (height >= 0.0 && lightHeight >= 0.0) below = 0.0;
    else if (height * lightHeight < 0.0)
      below = distance * -min(height, lightHeight) / abs(lightHeight - height);
    sum += lightIntensity[i].rgb * (cone * cosine / (distance * distance)) * exp(-sigmaT * below) *
           lightShadow(i, relative, normal, toLight, distance);
  }
  return sum;
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(depthTexture, pixel, 0).r;
  if (isSkyDepth(depth, int(projectionZ.z))) {
    // Above water the sky shows; below, the water surface pass draws Snell's window over it.
    outRadiance = cameraHeight.x >= 0.0 ? vec4(skyRadiance(viewDirection(uv), sunDirection.xyz), 1.0)
                                        : vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  vec3 relative = reconstructRelative(uv, depth);
  vec3 normal = decodeNormal(texelFetch(normalTexture, pixel, 0), NORMAL_OCTAHEDRAL);
  vec3 albedo = texelFetch(albedoTexture, pixel, 0).rgb;
  float height = cameraHeight.x + relative.y;  // metres above the water plane
  vec3 sigmaT = absorption.rgb + scattering.rgb;

  vec3 light = vec3(0.0);
  // Under the water the sun's light is the plugin's: its caustics, at intensity 1/pi with the
  // sun's beam below the surface (sun_light.h), are the direct underwater sun, flat water's
  // exactly and a wavy sea's redistributed. Lighting it here too would count the sun twice.
  if (sunDirection.w > 0.0 && height >= 0.0)
    light += sunIrradiance.rgb * max(dot(normal, sunDirection.xyz), 0.0) *
             sunShadow(shadowMap, relative, normal);
  light += localLights(relative, normal, height, sigmaT);
  // Sky light from above, attenuated with depth, weighted toward up-facing surfaces.
  float skyFacing = 0.5 + 0.5 * normal.y;
  vec3 ambientHere = height < 0.0 ? ambient.rgb * exp(-sigmaT * -height) : ambient.rgb * 1.3;
  light += ambientHere * skyFacing;
  outRadiance = vec4(albedo * light / 3.14159265, 1.0);
}
