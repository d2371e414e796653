#version 450 core
// Front map (nearest surface, normal facing the light) or back map (farthest surface, normal
// facing away: the exit side for Wyman's double refraction). Alpha of the position target holds
// the caster index + 1 (0 = no caster).
#include "shared/common.h"
#include "shared/gbuffer_codec.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

#include "postfx/object_caustics/object_caustics_light.glsl"

layout(location = 2) uniform int casterIndex;
layout(location = 3) uniform int backFaces;  // 0: front map, 1: back map
layout(location = 4) uniform int flatNormals;

in vec3 worldPosition;
in vec3 worldNormal;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;

void main() {
  vec3 n = flatNormals != 0 ? cross(dFdx(worldPosition), dFdy(worldPosition)) : worldNormal;
  n = safeNormalize(n);
  vec3 l = lightRayAt(worldPosition);
  // A degenerate triangle or a zero normal: treat as normal incidence rather than NaN.
  if (dot(n, n) < 0.5) n = -l;
  // Winding and normal direction are the host's: orient by the side the map looks at.
  float side = backFaces != 0 ? 1.0 : -1.0;
  if (dot(n, l) * side < 0.0) n = -n;
  outPosition = vec4(worldPosition, float(casterIndex + 1));
  outNormal = vec4(n, 0.0);
}
