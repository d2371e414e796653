// Water optics the sample host uses in several passes (lighting, fog, water surface), compiled
// by C++ (tests) and GLSL. The plugin has its own; this is the host's light model.
#ifndef POSTFX_SHARED_SAMPLE_OPTICS_H
#define POSTFX_SHARED_SAMPLE_OPTICS_H
#include "shared/common.h"

SHARED_BEGIN

// Unpolarized Fresnel reflectance for light going from a medium of index n1 into n2, with
// cosI the cosine on the incident side. Returns 1 under total internal reflection.
SHARED_FN float fresnelReflectance(float cosI, float n1, float n2) {
  cosI = clamp(cosI, 0.0f, 1.0f);
  float eta = n1 / n2;
  float sinT2 = eta * eta * (1.0f - cosI * cosI);
  if (sinT2 >= 1.0f) return 1.0f;
  float cosT = sqrt(1.0f - sinT2);
  float rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
  float rp = (n1 * cosT - n2 * cosI) / (n1 * cosT + n2 * cosI);
  return 0.5f * (rs * rs + rp * rp);
}

// Length of the part of the segment a -> b (heights relative to the water plane) below y = 0.
SHARED_FN float submergedLength(float segmentLength, float heightA, float heightB) {
  if (heightA >= 0.0f && heightB >= 0.0f) return 0.0f;
  if (heightA <= 0.0f && heightB <= 0.0f) return segmentLength;
  float below = heightA < 0.0f ? -heightA : -heightB;
  return segmentLength * below / abs(heightA - heightB);
}

// Radiance the sky's light scatters toward the camera from infinitely deep water at `depth`:
// single scattering of the downwelling `ambient` irradiance, sigma_s / sigma_t of it, taken as
// a uniform hemisphere of radiance E / pi (scalar irradiance 2 E) through an isotropic phase
// function 1 / (4 pi): E / (2 pi). The sun's own in-scattering is the plugin's god rays.
SHARED_FN vec3 waterInscatter(vec3 sigmaS, vec3 sigmaT, vec3 ambient, float depth) {
  return sigmaS / max(sigmaT, vec3(1e-6f)) * ambient *
         (0.159154943f * exp(-sigmaT * max(depth, 0.0f)));
}

// A simple sky: zenith-to-horizon gradient plus the sun's disc and glow. dir is unit.
SHARED_FN vec3 skyRadiance(vec3 dir, vec3 sunDir) {
  float up = max(dir.y, 0.0f);
  vec3 zenith = vec3(0.25f, 0.45f, 0.85f);
  vec3 horizon = vec3(0.75f, 0.85f, 0.95f);
  vec3 sky = mix(horizon, zenith, sqrt(up));
  if (dir.y < 0.0f) sky = mix(horizon, vec3(0.3f, 0.32f, 0.35f), min(-dir.y * 4.0f, 1.0f));
  float cosSun = max(dot(dir, sunDir), 0.0f);
  sky += vec3(1.0f, 0.9f, 0.7f) * (pow(cosSun, 600.0f) * 60.0f + pow(cosSun, 12.0f) * 0.4f);
  return sky;
}

SHARED_END

#endif
