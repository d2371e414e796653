// The host's sun shadow map at a camera-relative point (Feature::ShadowMask). Needs the caustics
// block (postfx_caustics_block.h) and sunShadowMap declared by the includer.
// Sun visibility at camera-relative p on a surface of normal n (zero for a point in the water
// column). The point is moved in world units before the lookup, so one setting fits any host's
// depth range: toward the light by SunShadowMap::bias metres, and along n by normalOffsetTexels
// of the map's texels at p times the sine of the angle to the light. A surface at angle theta
// to the light changes depth by tan(theta) per unit across the map, so the 2x2 PCF footprint
// (up to sqrt(2) texels away) sees it up to sqrt(2) texel tan(theta) nearer the light than p;
// moving p by o along n lifts it o / cos(theta) along the light: o >= sqrt(2) texel sin(theta).
float sunVisibility(vec3 p, vec3 n) {
  vec3 toLight = u.shadowLight.w > 0.5 ? normalize(u.shadowLight.xyz - p) : u.shadowLight.xyz;
  float cosine = clamp(dot(n, toLight), 0.0, 1.0);
  float sine = sqrt(max(1.0 - cosine * cosine, 0.0));
  vec2 mapSize = vec2(textureSize(sunShadowMap, 0));
  float texelsAtP = abs((u.shadowMatrix * vec4(p, 1.0)).w) *
                    max(u.shadowNormalOffset.x / mapSize.x, u.shadowNormalOffset.y / mapSize.y);
  vec3 moved = p + toLight * u.shadowParams.x + n * (texelsAtP * sine);
  vec4 clip = u.shadowMatrix * vec4(moved, 1.0);
  if (!(clip.w > 0.0)) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  if (!(abs(ndc.x) <= 1.0 && abs(ndc.y) <= 1.0)) return 1.0;  // outside the map: lit
  float ref = u.shadowParams.y > 0.5 ? ndc.z * 0.5 + 0.5 : ndc.z;
  return texture(sunShadowMap, vec3(ndc.xy * 0.5 + 0.5, clamp(ref, 0.0, 1.0)));
}
