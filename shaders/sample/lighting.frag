#version 450 core
// Deferred lighting: sun (refracted and attenuated under water, shadowed) and sky ambient.
// No fog here: the composite pass fogs this light, then the plugin adds its own (attenuated).
#include "shared/gbuffer_codec.h"
#include "shared/sample_frame.h"
#include "shared/sample_optics.h"
#include "sample/reconstruct.glsl"
in vec2 uv;
layout(binding = 0) uniform sampler2D depthTexture;
layout(binding = 1) uniform sampler2D normalTexture;
layout(binding = 2) uniform sampler2D albedoTexture;
layout(binding = 3) uniform sampler2DShadow shadowMap;
out vec4 outRadiance;

float sunShadow(vec3 relative, vec3 normal) {
  // Normal offset by a texel hides acne on slopes without peter-panning.
  vec3 biased = relative + normal * waterParams.y * 1.5;
  vec4 clip = shadowViewProjection * vec4(biased, 1.0);
  vec3 coord = clip.xyz / clip.w;
  coord.xy = coord.xy * 0.5 + 0.5;
  if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0)))) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(shadowMap, 0));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(shadowMap, vec3(coord.xy + vec2(x, y) * texel, coord.z - 0.0005));
  return lit / 9.0;
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
  if (sunDirection.w > 0.0) {
    vec3 toSun = height < 0.0 ? refractedSun.xyz : sunDirection.xyz;
    float cosine = max(dot(normal, toSun), 0.0);
    vec3 transmitted = sunIrradiance.rgb;
    if (height < 0.0) {
      // Beam through the surface (1 - Fresnel) and down the slanted path to this depth.
      float path = -height / max(refractedSun.y, 1e-3);
      transmitted *= refractedSun.w * exp(-sigmaT * path);
    }
    light += transmitted * cosine * sunShadow(relative, normal);
  }
  // Sky light from above, attenuated with depth, weighted toward up-facing surfaces.
  float skyFacing = 0.5 + 0.5 * normal.y;
  vec3 ambientHere = height < 0.0 ? ambient.rgb * exp(-sigmaT * -height) : ambient.rgb * 1.3;
  light += ambientHere * skyFacing;
  outRadiance = vec4(albedo * light / 3.14159265, 1.0);
}
