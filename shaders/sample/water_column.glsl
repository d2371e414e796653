// What a view ray that enters the water and meets nothing collects: infinitely deep water seen
// from the camera's depth. The fog pass writes it and the surface pass adds to it, so both must
// take it from here.
vec3 deepWaterColour() {
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  return waterInscatter(scattering.rgb, sigmaT, ambient.rgb, max(-cameraHeight.x, 0.0));
}

// The fog between the camera and a camera-relative point: what reaches the camera of the
// radiance leaving the point (transmittance), and the light the water column adds (in-scatter).
void viewFog(vec3 relative, out vec3 transmittance, out vec3 inscatter) {
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  float heightA = cameraHeight.x, heightB = cameraHeight.x + relative.y;
  float path = submergedLength(length(relative), heightA, heightB);
  transmittance = exp(-sigmaT * path);
  float meanDepth = -0.5 * (min(heightA, 0.0) + min(heightB, 0.0));
  inscatter = waterInscatter(scattering.rgb, sigmaT, ambient.rgb, meanDepth) * (1.0 - transmittance);
}
