#version 450 core
// Runs the shared reconstruction and normal codec on the GPU so a test can compare them with
// the C++ mirror bit for bit (same source, different compiler).
#include "shared/gbuffer_codec.h"
layout(local_size_x = 64) in;

struct Case {
  vec4 uvDepth;   // uv.xy, window depth, convention (as float)
  vec4 xyParams;
  vec4 zParams;   // P22, P32, normal encoding (as float), unused
  vec4 normal;    // input for the codec round trip
};
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };  // 2 per case
uniform int caseCount;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= uint(caseCount)) return;
  Case c = cases[i];
  vec3 view = viewPositionFromDepth(c.uvDepth.xy, c.uvDepth.z, c.xyParams, c.zParams.xy,
                                    int(c.uvDepth.w));
  int encoding = int(c.zParams.z);
  vec3 decoded = decodeNormal(encodeNormal(c.normal.xyz, encoding), encoding);
  results[2u * i] = vec4(view, 0.0);
  results[2u * i + 1u] = vec4(decoded, 0.0);
}
