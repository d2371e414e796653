#version 450 core
// Depth from a point or spot light: camera-relative positions into the light's clip space.
layout(location = 0) in vec3 inPosition;
uniform mat4 modelRelative;
uniform mat4 lightViewProjection;  // camera-relative world -> light clip
void main() { gl_Position = lightViewProjection * (modelRelative * vec4(inPosition, 1.0)); }
