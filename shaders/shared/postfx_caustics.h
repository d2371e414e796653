// Caustic math of seed 002 section 4 and the attenuation around it, shared by C++ and GLSL:
// the shader runs these bodies, and the tests evaluate the very same ones on the CPU.
#ifndef POSTFX_SHARED_CAUSTICS_H
#define POSTFX_SHARED_CAUSTICS_H
#include "shared/common.h"

SHARED_BEGIN

// Slopes beyond this are no water a renderer draws; clamping keeps normalize() well scaled.
SHARED_CONST float CAUSTICS_MAX_SLOPE = 64.0f;

// A NaN or infinite slope sum (broken texture, Inf - Inf) becomes flat water rather than
// spreading NaN through the frame. Comparisons with NaN are false, so NaN takes the else arm.
SHARED_FN vec2 sanitizeSlopes(vec2 s) {
  return vec2(abs(s.x) <= CAUSTICS_MAX_SLOPE ? s.x : 0.0f,
              abs(s.y) <= CAUSTICS_MAX_SLOPE ? s.y : 0.0f);
}

// Water normal from the summed cascade slopes (dh/dx, dh/dz); never zero-length, as y = 1.
SHARED_FN vec3 waterNormalFromSlopes(vec2 slopes) {
  vec2 s = sanitizeSlopes(slopes);
  return normalize(vec3(-s.x, 1.0f, -s.y));
}

// Eq. (1): omega = exp(-tau * a^2), a the cosine between a ray and the reference vector that is
// perpendicular to the unperturbed ray (a = 0 where the surface is flat, so flat water gives 1).
SHARED_FN float causticOmegaOfCosine(float a, float tau) {
  float c = clamp(a, -1.0f, 1.0f);
  return exp(-tau * (c * c));
}

SHARED_FN float causticOmega(vec3 ray, vec3 reference, float tau) {
  return causticOmegaOfCosine(dot(ray, reference), tau);
}

// The cosines a of eq. (1) need no refracted or reflected vector, only the three dot products
// they are made of. With I the incident sun, N the water normal, r the reference, c = N.I and
// k = 1 - eta^2 (1 - c^2), GLSL's refract() is eta I - (eta c + sqrt(k)) N (0 when k < 0) and
// reflect() is I - 2 c N, so
//   r.refract = eta (I.r) - (eta c + sqrt(k)) (N.r),   r.reflect = I.r - 2 c (N.r).
// The same model to rounding, at a fraction of the arithmetic (it runs per god-ray sample).
SHARED_FN float refractedCosine(float eta, float c, float incidentDotRef, float normalDotRef) {
  float k = 1.0f - eta * eta * (1.0f - c * c);
  return k < 0.0f ? 0.0f : eta * incidentDotRef - (eta * c + sqrt(k)) * normalDotRef;
}

// The seed's caustic factor for one wavelength: the sun ray refracted (eta = 1 / IOR) and
// reflected by the local water normal, each turned into omega, blended by reflectionWeight.
// `reference` is perpendicular to the plane of incidence, hence to both unperturbed rays.
SHARED_FN float causticFactor(vec3 towardSun, vec3 waterNormal, float eta, vec3 reference,
                              float tau, float reflectionWeight) {
  vec3 incident = -towardSun;
  float c = dot(waterNormal, incident);
  float incidentDotRef = dot(incident, reference), normalDotRef = dot(waterNormal, reference);
  float omegaT = causticOmegaOfCosine(refractedCosine(eta, c, incidentDotRef, normalDotRef), tau);
  float omegaR = causticOmegaOfCosine(incidentDotRef - 2.0f * c * normalDotRef, tau);
  return mix(omegaT, omegaR, reflectionWeight);
}

// causticFactor for three wavelengths (per-channel eta, dispersion): the reflected ray is the
// same for all of them, so its omega is computed once.
SHARED_FN vec3 causticFactorRgb(vec3 towardSun, vec3 waterNormal, vec3 eta, vec3 reference,
                                float tau, float reflectionWeight) {
  vec3 incident = -towardSun;
  float c = dot(waterNormal, incident);
  float incidentDotRef = dot(incident, reference), normalDotRef = dot(waterNormal, reference);
  vec3 omegaT =
      vec3(causticOmegaOfCosine(refractedCosine(eta.x, c, incidentDotRef, normalDotRef), tau),
           causticOmegaOfCosine(refractedCosine(eta.y, c, incidentDotRef, normalDotRef), tau),
           causticOmegaOfCosine(refractedCosine(eta.z, c, incidentDotRef, normalDotRef), tau));
  float omegaR = causticOmegaOfCosine(incidentDotRef - 2.0f * c * normalDotRef, tau);
  return mix(omegaT, vec3(omegaR), reflectionWeight);
}

// Beer-Lambert transmittance along the refracted sun path to a receiver `depthBelow` metres
// under the level: `absorptionPerDepth` is sigma / cos(theta_t), folded on the CPU.
SHARED_FN vec3 causticTransmittance(vec3 absorptionPerDepth, float depthBelow) {
  return exp(-absorptionPerDepth * max(depthBelow, 0.0f));
}

// Caustics ramp in over `fadeDepth` metres below the surface (smoothstep; 0 disables).
SHARED_FN float causticSurfaceFade(float depthBelow, float fadeDepth) {
  if (!(depthBelow > 0.0f)) return 0.0f;
  if (!(fadeDepth > 0.0f)) return 1.0f;
  float t = clamp(depthBelow / fadeDepth, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// Albedo as a reflectance: NaN/negative from a broken G-buffer become 0, HDR values clamp to 1.
SHARED_FN vec3 sanitizeAlbedo(vec3 a) {
  return vec3(a.x >= 0.0f ? min(a.x, 1.0f) : 0.0f, a.y >= 0.0f ? min(a.y, 1.0f) : 0.0f,
              a.z >= 0.0f ? min(a.z, 1.0f) : 0.0f);
}

SHARED_END

#endif
