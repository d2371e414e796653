// Lit share of the sun at a camera-relative point (3x3 PCF of the sun's shadow map), 1 outside
// the map. The map is fitted along the refracted sun (renderer.cpp), bent above the level where
// the scene asks for it (shadow_space.glsl).
#include "sample/shadow_space.glsl"
float sunShadow(sampler2DShadow map, vec3 relative, vec3 normal) {
  // Normal offset by a texel hides acne on slopes without peter-panning.
  vec3 biased = relative + normal * waterParams.y * 1.5;
  vec4 clip = shadowViewProjection * vec4(shadowSpace(biased), 1.0);
  vec3 coord = clip.xyz / clip.w;
  coord.xy = coord.xy * 0.5 + 0.5;
  if (any(lessThan(coord, vec3(0.0))) || any(greaterThan(coord, vec3(1.0)))) return 1.0;
  vec2 texel = 1.0 / vec2(textureSize(map, 0));
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += texture(map, vec3(coord.xy + vec2(x, y) * texel, coord.z - 0.0005));
  return lit / 9.0;
}
