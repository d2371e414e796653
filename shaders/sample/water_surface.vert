#version 450 core
// Displaced water surface: a camera-centred polar grid (dense near the camera, kilometres
// wide) displaced by the ocean's cascades.
#include "shared/sample_frame.h"
layout(location = 0) in vec2 gridXZ;  // camera-relative, metres
layout(binding = 4) uniform sampler2DArray displacement;
out vec2 surfaceXZ;  // camera-relative undisplaced position (the slope lookup uses it)
out vec3 relativePosition;
void main() {
  vec3 offset = vec3(0.0);
  int count = int(cascadeInfo.x);
  for (int c = 0; c < count; ++c) {
    vec2 tileUv = gridXZ * cascadeTile[c].y + cascadeTile[c].zw;
    offset += textureLod(displacement, vec3(tileUv, float(c)), 0.0).xyz;
  }
  // Far rings fall below a texel per vertex: fade the displacement so they do not alias.
  offset *= clamp(1.5 - length(gridXZ) / 600.0, 0.0, 1.0);
  surfaceXZ = gridXZ;
  relativePosition = vec3(gridXZ.x + offset.x, -cameraHeight.x + offset.y, gridXZ.y + offset.z);
  gl_Position = viewProjection * vec4(relativePosition, 1.0);
}
