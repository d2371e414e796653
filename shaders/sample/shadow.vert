#version 450 core
#include "shared/sample_frame.h"
#include "sample/shadow_space.glsl"
layout(location = 0) in vec3 inPosition;
uniform mat4 modelRelative;
void main() {
  vec4 relative = modelRelative * vec4(inPosition, 1.0);
  relative.xyz = shadowSpace(relative.xyz);
  gl_Position = shadowViewProjection * relative;
}
