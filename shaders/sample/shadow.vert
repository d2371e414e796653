#version 450 core
#include "shared/sample_frame.h"
layout(location = 0) in vec3 inPosition;
uniform mat4 modelRelative;
void main() { gl_Position = shadowViewProjection * (modelRelative * vec4(inPosition, 1.0)); }
