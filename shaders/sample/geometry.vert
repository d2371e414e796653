#version 450 core
#include "shared/sample_frame.h"
layout(location = 0) in vec3 inPosition;
layout(location = 1) in vec3 inNormal;
uniform mat4 modelRelative;  // model -> camera-relative world (translation taken in double)
uniform mat3 normalMatrix;
out vec3 worldNormal;
out vec3 relativePosition;  // camera-relative world (m)
// The forward metal pass draws over the G-buffer's own depth with GL_EQUAL: both programs use
// this shader, and invariance is what makes their depths equal bit for bit.
invariant gl_Position;
void main() {
  worldNormal = normalMatrix * inNormal;
  relativePosition = (modelRelative * vec4(inPosition, 1.0)).xyz;
  gl_Position = viewProjection * vec4(relativePosition, 1.0);
}
