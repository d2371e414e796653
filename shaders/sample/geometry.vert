#version 450 core
#include "shared/sample_frame.h"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
uniform mat4 modelRelative;  // model -> camera-relative world (translation taken in double)
uniform mat3 normalMatrix;
out vec3 worldNormal;
void main() {
  worldNormal = normalMatrix * inNormal;
  gl_Position = viewProjection * (modelRelative * vec4(inPosition, 1.0));
}
