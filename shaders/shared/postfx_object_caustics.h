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

// Truncation-corrected Gaussian splat weight per texel: the discrete sum over the square point
// sprite of half side 3 sigma is 1 (flux is conserved), see the splat pass.
SHARED_FN float splatWeight(vec2 offsetTexels, float sigma) {
  float s2 = sigma * sigma;
  // 1 / (2 pi sigma^2), divided by the square's share of the Gaussian, erf(3/sqrt 2)^2.
  return exp(-dot(offsetTexels, offsetTexels) / (2.0f * s2)) * (0.15915494f / 0.99460f) / s2;
}

// Point-sprite side (texels, odd) that holds +-3 sigma around a centre anywhere in its texel.
SHARED_FN float splatSpriteSize(float sigma) {
  return 2.0f * ceil(3.0f * sigma) + 1.0f;
}

SHARED_END

#endif
