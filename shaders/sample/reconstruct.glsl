// Camera-relative world position of a pixel, from the G-buffer depth (sample frame constants).
vec3 reconstructRelative(vec2 uv, float depth) {
  vec3 view = viewPositionFromDepth(uv, depth, projectionXY, projectionZ.xy, int(projectionZ.z));
  return mat3(cameraToWorld) * view;
}
vec3 viewDirection(vec2 uv) { return normalize(reconstructRelative(uv, 0.5)); }
