#version 450 core
// One triangle covering the viewport; z = 0.5 w lies inside both clip-control depth ranges, so
// the host's glClipControl never clips it.
void main() {
  vec2 p = vec2(float((gl_VertexID & 1) << 2), float((gl_VertexID & 2) << 1)) - 1.0;
  gl_Position = vec4(p, 0.5, 1.0);
}
