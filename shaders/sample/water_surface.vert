#version 450 core
// Displaced water surface: a camera-centred polar grid (dense near the camera, kilometres
// wide) displaced by the ocean's cascades, plus a local water region's height inside it (Add:
// on the sea; Replace: instead of it); or, where there is no sea, the region's own square.
#include "shared/sample_frame.h"
#include "sample/local_water.glsl"
// Camera-relative xz (m) of the sea's grid, or the region's square in [-0.5, 0.5]^2 (see
// localWaterExtent.w).
layout(location = 0) in vec2 gridXZ;
layout(binding = 4) uniform sampler2DArray displacement;
out vec2 surfaceXZ;  // camera-relative undisplaced position (the slope lookup uses it)
out vec3 relativePosition;
void main() {
  vec2 xz = localWaterExtent.w > 0.5 ? localWaterSquareToRelative(gridXZ) : gridXZ;
  vec2 uv;
  bool local = localWaterUv(xz, uv);
  vec3 offset = vec3(0.0);
  // Inside a Replace region the sea is not there: the region's water is all there is.
  int count = local && localWaterMode() == kLocalWaterReplace ? 0 : int(cascadeInfo.x);
  for (int c = 0; c < count; ++c) {
    vec2 tileUv = xz * cascadeTile[c].y + cascadeTile[c].zw;
    offset += textureLod(displacement, vec3(tileUv, float(c)), 0.0).xyz;
  }
  // Far rings fall below a texel per vertex: fade the displacement so they do not alias.
  offset *= clamp(1.5 - length(xz) / 600.0, 0.0, 1.0);
  if (local) offset.y += localWaterHeight(uv);
  surfaceXZ = xz;
  relativePosition = vec3(xz.x + offset.x, -cameraHeight.x + offset.y, xz.y + offset.z);
  gl_Position = viewProjection * vec4(relativePosition, 1.0);
}
