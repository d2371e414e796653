// What a view ray that enters the water and meets nothing collects: infinitely deep water seen
// from the camera's depth. The fog pass writes it and the surface pass adds to it, so both must
// take it from here.
vec3 deepWaterColour() {
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  return waterInscatter(scattering.rgb, sigmaT, ambient.rgb, max(-cameraHeight.x, 0.0));
}
