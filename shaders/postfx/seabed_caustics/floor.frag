#version 450 core
// Benchmark floor: one fetch of every input the caustics pass reads (each G-buffer texture, each
// water cascade layer, the shadow map), and its writes, with no math. Adds exactly 0 (u.shadowParams.w is 0 and NaN is filtered), so it is invisible.
#include "postfx/seabed_caustics/caustics_io.glsl"

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 sum = texelFetch(gbufferDepth, pixel, 0) + texelFetch(gbufferNormal, pixel, 0) +
             texelFetch(gbufferAlbedo, pixel, 0);
  int cascades = int(u.oblique.w);
  for (int c = 0; c < POSTFX_CASCADE_SLOTS; ++c) {  // unrolled, like the caustics' lookups
    if (c < cascades)
      sum += textureLod(waterSurface, WATER_COORD(gl_FragCoord.xy * u.viewport.xy, c), 0.0);
  }
#if POSTFX_SHADOW_MASK
  sum.x += texture(sunShadowMap, vec3(gl_FragCoord.xy * u.viewport.xy, 0.5));
#endif
  float v = sum.x + sum.y + sum.z + sum.w;
  v = abs(v) < 1e30 ? v * u.shadowParams.w : 0.0;
  outLight = vec4(v);
#if POSTFX_RAW_OUTPUT
  outRaw = v;
#endif
}
