// Caustic math of [1] section 4 (ray deviation) and the attenuation around it, shared by C++
// and GLSL: the shader runs these bodies, and the tests evaluate the very same ones on the CPU.
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

// Eq. (1): omega = exp(-tau * a^2). The paper [1] takes a as the cosine between the ray and one
// reference vector perpendicular to the unperturbed ray, i.e. the deviation across the plane of
// incidence only, so its pattern is streaked along the sun's azimuth (gradient energy across /
// along 3.8-4.0 with the sun near the zenith, against 1.1-1.25 in traced light). Here a is the
// sine of the angle between the ray and its flat-water ray, the whole deviation: isotropic for a
// high sun, and still a = 0 (omega = 1) where the water is flat. From the difference d of the two
// unit rays, |d|^2 = 2 - 2 cos, so sin^2 = |d|^2 (1 - |d|^2 / 4): exact to the rounding of d
// even for the faintest ripple, where 1 - cos^2 would cancel (1e-7 of a^2, 0.1 of omega at
// tau 1e6).
SHARED_FN float causticOmegaOfDeviation(vec3 ray, vec3 unperturbed, float tau) {
  vec3 d = ray - unperturbed;
  float dd = dot(d, d);
  return exp(-tau * clamp(dd * (1.0f - 0.25f * dd), 0.0f, 1.0f));
}

// The sun refracted by flat water (normal +y): the unperturbed ray of eta = 1 / IOR.
SHARED_FN vec3 flatRefracted(vec3 incident, float eta) {
  float k = max(1.0f - eta * eta * (1.0f - incident.y * incident.y), 0.0f);
  return vec3(eta * incident.x, -sqrt(k), eta * incident.z);
}

// omega of the sun refracted with eta through the water normal (c = N.I). GLSL's refract() is
// eta I - (eta c + sqrt(k)) N with k = 1 - eta^2 (1 - c^2); k < 0 is total internal reflection
// (eta > 1 only): nothing is transmitted, a^2 = 1.
SHARED_FN float refractedOmega(vec3 incident, vec3 waterNormal, float c, float eta, float tau) {
  float k = 1.0f - eta * eta * (1.0f - c * c);
  vec3 refracted = eta * incident - (eta * c + sqrt(max(k, 0.0f))) * waterNormal;
  float omega = causticOmegaOfDeviation(refracted, flatRefracted(incident, eta), tau);
  return k < 0.0f ? exp(-tau) : omega;
}

// omega of the sun reflected by the water normal, I - 2 c N, against its flat-water reflection.
SHARED_FN float reflectedOmega(vec3 incident, vec3 waterNormal, float c, float tau) {
  return causticOmegaOfDeviation(incident - 2.0f * c * waterNormal,
                                 vec3(incident.x, -incident.y, incident.z), tau);
}

// The ray-deviation caustic factor for one wavelength ([1] with the full deviation): the
// sun ray refracted (eta = 1 / IOR) and reflected by the local water normal, each turned into
// omega, blended by reflectionWeight.
SHARED_FN float causticFactor(vec3 towardSun, vec3 waterNormal, float eta, float tau,
                              float reflectionWeight) {
  vec3 incident = -towardSun;
  float c = dot(waterNormal, incident);
  return mix(refractedOmega(incident, waterNormal, c, eta, tau),
             reflectedOmega(incident, waterNormal, c, tau), reflectionWeight);
}

// causticFactor for three wavelengths (per-channel eta, dispersion): the reflected ray is the
// same for all of them, so its omega is computed once.
SHARED_FN vec3 causticFactorRgb(vec3 towardSun, vec3 waterNormal, vec3 eta, float tau,
                                float reflectionWeight) {
  vec3 incident = -towardSun;
  float c = dot(waterNormal, incident);
  vec3 omegaT = vec3(refractedOmega(incident, waterNormal, c, eta.x, tau),
                     refractedOmega(incident, waterNormal, c, eta.y, tau),
                     refractedOmega(incident, waterNormal, c, eta.z, tau));
  return mix(omegaT, vec3(reflectedOmega(incident, waterNormal, c, tau)), reflectionWeight);
}

// The paper's own form, kept for the god rays: a is the cosine between the ray and `across`, the
// unit vector perpendicular to the plane of incidence, i.e. only the deviation across that
// plane. Along a view ray through the water it gives shafts as sheets along the sun's azimuth;
// the god-ray tests, reference (sample_app/reference/godray_reference.cpp) and report rows are
// calibrated against it. With I the incident sun, N the water normal, c = N.I and
// k = 1 - eta^2 (1 - c^2): across.refract = eta (I.across) - (eta c + sqrt(k)) (N.across) (0 when
// k < 0), across.reflect = I.across - 2 c (N.across): dot products only, as it runs per sample.
SHARED_FN float causticOmegaOfCosine(float a, float tau) {
  float c = clamp(a, -1.0f, 1.0f);
  return exp(-tau * (c * c));
}

SHARED_FN float causticFactorAcrossIncidence(vec3 towardSun, vec3 waterNormal, float eta,
                                             vec3 across, float tau, float reflectionWeight) {
  vec3 incident = -towardSun;
  float c = dot(waterNormal, incident);
  float incidentDotAcross = dot(incident, across), normalDotAcross = dot(waterNormal, across);
  float k = 1.0f - eta * eta * (1.0f - c * c);
  float refracted =
      k < 0.0f ? 0.0f : eta * incidentDotAcross - (eta * c + sqrt(max(k, 0.0f))) * normalDotAcross;
  float omegaT = causticOmegaOfCosine(refracted, tau);
  float omegaR = causticOmegaOfCosine(incidentDotAcross - 2.0f * c * normalDotAcross, tau);
  return mix(omegaT, omegaR, reflectionWeight);
}

// Beer-Lambert transmittance along the refracted sun path to a receiver `depthBelow` metres
// under the level: `absorptionPerDepth` is sigma / cos(theta_t), folded on the CPU.
SHARED_FN vec3 causticTransmittance(vec3 absorptionPerDepth, float depthBelow) {
  return exp(-absorptionPerDepth * max(depthBelow, 0.0f));
}

// Metres of the view ray from the camera to a receiver `depthBelow` under the level that lie
// below the level, `levelRelative` = level - camera height: all of it from a camera under water,
// the part past the surface from one above (the ray is straight, so the fraction is the ratio
// of the heights).
SHARED_FN float submergedViewLength(float distance, float depthBelow, float levelRelative) {
  if (levelRelative >= 0.0f) return distance;
  return distance * clamp(depthBelow / max(depthBelow - levelRelative, 1e-30f), 0.0f, 1.0f);
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
