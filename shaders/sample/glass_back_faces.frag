#version 450 core
// The glass's far side as the camera sees through it (Wyman 2005, two-surface image-space
// refraction): per pixel, the nearest surface that faces away from the camera, its outward
// normal and its distance from the camera. Front faces are discarded here, whatever the
// mesh's winding, by their normal.
in vec3 worldNormal;
in vec3 relativePosition;
out vec4 outBack;  // xyz: outward unit normal (world); w: distance from the camera (m), 0: none
void main() {
  vec3 n = normalize(worldNormal);
  if (dot(n, relativePosition) <= 0.0) discard;
  outBack = vec4(n, length(relativePosition));
}
