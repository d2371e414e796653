#version 450 core
// Exposure, ACES filmic fit (Narkowicz 2015) and sRGB encoding into an RGBA8 target.
#include "shared/sample_frame.h"
in vec2 uv;
layout(binding = 0) uniform sampler2D radianceTexture;
out vec4 outColor;
vec3 aces(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
vec3 srgbEncode(vec3 c) {
  return mix(c * 12.92, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(vec3(0.0031308), c));
}
void main() {
  vec3 radiance = texelFetch(radianceTexture, ivec2(gl_FragCoord.xy), 0).rgb;
  // A NaN from anywhere upstream must not reach the image as garbage; show it as magenta in
  // debugging, but the tests assert it never happens.
  if (any(isnan(radiance)) || any(isinf(radiance))) radiance = vec3(1e4, 0.0, 1e4);
  outColor = vec4(srgbEncode(aces(radiance * cascadeInfo.y)), 1.0);
}
