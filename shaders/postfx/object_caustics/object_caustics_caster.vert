#version 450 core
// Caster maps ([2], section III.B step 2): each caster drawn from the light's view fitted
// to the casters (the sun's orthographic one, or a local light's perspective one), writing
// anchor-relative positions and normals.
#include "shared/common.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

layout(location = 0) in vec3 modelPosition;
layout(location = 1) in vec3 modelNormal;  // (0,0,0) when the mesh has none (attribute off)

layout(location = 0) uniform mat4 modelToAnchor;
layout(location = 1) uniform mat4 normalToWorld;  // inverse transpose of the model's 3x3

out vec3 worldPosition;
out vec3 worldNormal;

void main() {
  vec4 p = modelToAnchor * vec4(modelPosition, 1.0);
  worldPosition = p.xyz;
  worldNormal = mat3(normalToWorld) * modelNormal;
  gl_Position = u.casterClip * p;
}
