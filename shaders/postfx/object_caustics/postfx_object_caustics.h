// Optics of the object caustics, compiled by both C++ (tests mirror the GPU) and GLSL.
#ifndef POSTFX_SHARED_OBJECT_CAUSTICS_H
#define POSTFX_SHARED_OBJECT_CAUSTICS_H
#include "shared/common.h"

SHARED_BEGIN

// Unpolarised Fresnel reflectance of a dielectric interface. cosI: cosine of the incidence
// angle (>= 0), eta: IOR of the far side over the near side. 1 under total internal reflection.
SHARED_FN float fresnelDielectric(float cosI, float eta) {
  cosI = clamp(cosI, 0.0f, 1.0f);
  float sinT2 = (1.0f - cosI * cosI) / (eta * eta);
  if (sinT2 >= 1.0f) return 1.0f;
  float cosT = sqrt(1.0f - sinT2);
  float rs = (cosI - eta * cosT) / (cosI + eta * cosT);
  float rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5f * (rs * rs + rp * rp);
}

// Schlick's approximation for metals, F0 per channel.
SHARED_FN vec3 fresnelSchlick(float cosI, vec3 f0) {
  float m = 1.0f - clamp(cosI, 0.0f, 1.0f);
  float m5 = m * m * m * m * m;
  return f0 + (vec3(1.0f) - f0) * m5;
}

// Covariance (texels^2; xx, xy, yy) of one ray's Gaussian splat: an isotropic part sigma0 (the
// splat radius and the roughness cone) plus a quarter of the outer products of the vectors to
// where the neighbouring rays land. Where light diverges those vectors are longer than the splat
// is wide, and a lattice of narrow Gaussians shows as rings (moire); widening each along its own
// lattice vectors by half their length leaves a ripple of 2 exp(-pi^2 / 2) < 1.5 % of the mean.
// Along a direction in which the rays converge (towards a caustic point or line) the vector is
// short and the splat stays as narrow as sigma0, so the caustic keeps its sharpness.
SHARED_FN vec3 splatCovariance(float sigma0, vec2 alongX, vec2 alongY, float maxSigma,
                               float roundness) {
  vec3 c = vec3(0.25f * (alongX.x * alongX.x + alongY.x * alongY.x),
                0.25f * (alongX.x * alongX.y + alongY.x * alongY.y),
                0.25f * (alongX.y * alongX.y + alongY.y * alongY.y));
  // Bound the width along each principal axis separately: shortening the vectors instead would
  // also shorten their narrow component, and a ray fanning out far along one axis would lose
  // the width it needs across it (radial streaks in a lens's outer halo).
  float mean = 0.5f * (c.x + c.z);
  float spread = sqrt(0.25f * (c.x - c.z) * (c.x - c.z) + c.y * c.y);
  float cap = maxSigma * maxSigma;
  float hi = min(mean + spread, cap);
  float lo = min(max(mean - spread, roundness * hi), cap);
  vec2 axis = abs(c.y) > 1e-12f * (mean + 1e-30f)
                  ? normalize(vec2(mean + spread - c.z, c.y))
                  : (c.x >= c.z ? vec2(1.0f, 0.0f) : vec2(0.0f, 1.0f));
  float s2 = min(sigma0, maxSigma);
  s2 = s2 * s2 + lo;
  return vec3(s2 + (hi - lo) * axis.x * axis.x, (hi - lo) * axis.x * axis.y,
              s2 + (hi - lo) * axis.y * axis.y);
}

// Truncation-corrected Gaussian splat weight per texel for the covariance (xx, xy, yy): the sum
// over the point sprite (a square of half side 3 sigma along each axis) is 1 within 0.3 %: the
// square holds erf(3/sqrt 2)^2 = 0.99460 of an axis-aligned Gaussian and up to 0.9973 of a fully
// correlated one. An isotropic covariance gives exactly the former, flux-conserving, splat.
SHARED_FN float splatWeight(vec2 offsetTexels, vec3 covariance) {
  float det = covariance.x * covariance.z - covariance.y * covariance.y;
  vec2 o = offsetTexels;
  float q =
      (covariance.z * o.x * o.x - 2.0f * covariance.y * o.x * o.y + covariance.x * o.y * o.y) / det;
  // 1 / (2 pi sqrt(det)), divided by the square's share of the Gaussian.
  return exp(-0.5f * q) * (0.15915494f / 0.99460f) / sqrt(det);
}

// Point-sprite side (texels, odd) that holds +-3 sigma around a centre anywhere in its texel,
// sigma the larger standard deviation along the map's axes.
SHARED_FN float splatSpriteSize(float sigma) {
  return 2.0f * ceil(3.0f * sigma) + 1.0f;
}

// A spot light's cone: 1 within the inner half-angle, 0 from the outer one on, a smoothstep in
// between (angles in radians from the spot's axis; inner == outer is a hard edge).
SHARED_FN float spotConeFalloff(float angle, float outer, float inner) {
  if (!(angle < outer)) return 0.0f;
  if (angle <= inner) return 1.0f;
  float t = (outer - angle) / (outer - inner);
  return t * t * (3.0f - 2.0f * t);
}

// How much of a straight segment of the given length lies under the water, its ends at heights
// ya and yb relative to the water level (negative: under water).
SHARED_FN float submergedLength(float length, float ya, float yb) {
  float below = max(-ya, 0.0f) + max(-yb, 0.0f);
  return length * min(below / max(abs(ya - yb), 1e-30f), 1.0f);
}

SHARED_END

#endif
