#version 450 core
// Seed 003's temporal filter over the caustic map: history blended with this frame's splats.
// The history is first clamped to the 3x3 neighbourhood of the new map (the TAA bound), so a
// caustic that moved leaves no trail longer than one frame's blur.
#include "postfx/common/postfx_bindings.h"

layout(binding = POSTFX_OBJECT_UNIT_CURRENT_MAP) uniform sampler2D currentMap;
layout(binding = POSTFX_OBJECT_UNIT_HISTORY_MAP) uniform sampler2D historyMap;
layout(location = 0) uniform float historyWeight;

layout(location = 0) out vec4 outMap;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  ivec2 last = textureSize(currentMap, 0) - 1;
  vec4 current = texelFetch(currentMap, texel, 0);
  vec4 lo = current, hi = current;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      vec4 c = texelFetch(currentMap, clamp(texel + ivec2(i, j), ivec2(0), last), 0);
      lo = min(lo, c);
      hi = max(hi, c);
    }
  }
  vec4 history = clamp(texelFetch(historyMap, texel, 0), lo, hi);
  // No history (weight 0) must give exactly this frame: mix() would still multiply the
  // history by 0, and a NaN left in it by an earlier frame would survive that.
  outMap = historyWeight > 0.0 ? mix(current, history, historyWeight) : current;
}
