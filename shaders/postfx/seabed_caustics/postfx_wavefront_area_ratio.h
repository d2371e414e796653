// Wavefront area-ratio caustics [4], shared by C++ and GLSL: the irradiance pass's
// per-vertex refraction and the caustics pass's depth-layer interpolation, so the tests can
// evaluate exactly what the shaders do.
#ifndef POSTFX_SHARED_IRRADIANCE_H
#define POSTFX_SHARED_IRRADIANCE_H
#include "shared/common.h"
#include "postfx/seabed_caustics/postfx_caustics.h"

SHARED_BEGIN

// A height sum beyond this (or NaN/Inf) is a broken texture, taken as the mean level.
SHARED_CONST float CAUSTICS_MAX_HEIGHT = 1000.0f;
SHARED_CONST int IRRADIANCE_MAX_LAYERS = 8;

SHARED_FN float sanitizeHeight(float h) {
  return abs(h) <= CAUSTICS_MAX_HEIGHT ? h : 0.0f;
}

// Unpolarised Fresnel transmittance from air into water (index `ior`) at incidence cosine
// cosIncident: 1 - (Rs + Rp) / 2. 0 for light from behind the surface.
SHARED_FN float fresnelTransmittance(float cosIncident, float ior) {
  if (!(cosIncident > 0.0f)) return 0.0f;
  float ci = min(cosIncident, 1.0f);
  float st2 = (1.0f - ci * ci) / (ior * ior);
  float ct = sqrt(max(1.0f - st2, 0.0f));
  float rs = (ci - ior * ct) / (ci + ior * ct);
  float rp = (ior * ci - ct) / (ior * ci + ct);
  return clamp(1.0f - 0.5f * (rs * rs + rp * rp), 0.0f, 1.0f);
}

// Where the sun ray through the surface point (local, h) lands on a horizontal receiver
// `depth` metres under the mean level (xy), and its Fresnel transmittance relative to flat
// water (z). A ray that cannot go down (grazing normal) carries no light: z = 0.
SHARED_FN vec3 refractToReceiver(vec2 local, vec3 surface, vec3 towardSun, float ior,
                                 float invFlatTransmittance, float depth) {
  vec3 n = waterNormalFromSlopes(vec2(surface.x, surface.y));
  float h = sanitizeHeight(surface.z);
  vec3 t = refract(-towardSun, n, 1.0f / ior);
  if (!(t.y < -1e-4f)) return vec3(local, 0.0f);
  float path = max((-depth - h) / t.y, 0.0f);
  float transmit = fresnelTransmittance(dot(towardSun, n), ior) * invFlatTransmittance;
  return vec3(local + vec2(t.x, t.z) * path, transmit);
}

// Where the same sun ray crossed the mean level: its position in the incoming beam. The
// beam's area per triangle is the "original area" of the ratio. sunDrift = towardSun.xz / y.
SHARED_FN vec2 beamPosition(vec2 local, float height, vec2 sunDrift) {
  return local - sunDrift * sanitizeHeight(height);
}

// Depth of layer k from the two packed vec4s (layers 0-3, 4-7).
SHARED_FN float packedLayerDepth(vec4 depths0, vec4 depths1, int k) {
  return k < 4 ? depths0[k] : depths1[k - 4];
}

// Linear interpolation in depth between the layers around `depth`: (lower layer, upper layer,
// weight of the upper one). Layer -1 stands for the surface, where irradiance is 1; below the
// deepest layer it is used alone.
SHARED_FN vec3 layerBlend(float depth, vec4 depths0, vec4 depths1, int layers) {
  float above = 0.0f;
  int lower = -1;
  for (int k = 0; k < IRRADIANCE_MAX_LAYERS; ++k) {
    if (k >= layers) break;
    float d = packedLayerDepth(depths0, depths1, k);
    if (depth <= d) {
      float t = clamp((depth - above) / max(d - above, 1e-6f), 0.0f, 1.0f);
      return vec3(float(lower), float(k), t);
    }
    above = d;
    lower = k;
  }
  return vec3(float(lower), float(lower), 0.0f);
}

// Where a layer `layerDepth` deep is looked up for a receiver at xz, `depth` deep: the point
// its flat-water ray (through the same surface point) reaches at the layer's depth.
// oblique = refractedUp.xz / refractedUp.y, i.e. minus the drift per metre of depth.
SHARED_FN vec2 layerSamplePoint(vec2 xz, float depth, float layerDepth, vec2 oblique) {
  return xz + oblique * (depth - layerDepth);
}

SHARED_END

#endif
