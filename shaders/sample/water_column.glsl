// What a view ray that enters the water and meets nothing collects: infinitely deep water seen
// from the camera's depth. The fog pass writes it and the surface pass adds to it, so both must
// take it from here.
vec3 deepWaterColour() {
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  return waterInscatter(scattering.rgb, sigmaT, ambient.rgb, max(-cameraHeight.x, 0.0));
}

// What a view ray meets at the water surface from below, along unit `view`, the surface's
// normal `down` facing it: Snell's window shows the sky (skyRadiance with `sunDir`), outside it
// and by Fresnel within it the water reflects `deep`.
vec3 belowSurfaceRadiance(vec3 view, vec3 down, vec3 sunDir, vec3 deep) {
  float f = fresnelReflectance(max(-dot(view, down), 0.0), waterParams.x, 1.0);
  vec3 sky = f < 1.0 ? skyRadiance(normalize(refract(view, down, waterParams.x)), sunDir) : vec3(0.0);
  return (1.0 - f) * sky + f * deep;
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
