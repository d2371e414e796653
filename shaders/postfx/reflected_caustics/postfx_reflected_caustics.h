// Reflected caustics above the water (postfx/reflected_caustics.h), shared by C++ and GLSL: the
// grid's per-point reflection and the receivers' layer lookup, so that the tests evaluate
// exactly what the shaders do. Heights are metres above the mean level.
#ifndef POSTFX_SHARED_REFLECTED_CAUSTICS_H
#define POSTFX_SHARED_REFLECTED_CAUSTICS_H
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
#include "shared/common.h"

SHARED_BEGIN

SHARED_CONST int REFLECTED_MAX_LAYERS = 8;
// Above the highest layer the pattern fades to its mean over this fraction of maxHeight.
SHARED_CONST float REFLECTED_TOP_FADE = 0.5f;

// Unpolarised Fresnel reflectance from air onto water (index `ior`) at incidence cosine
// cosIncident: exactly 1 - fresnelTransmittance, so that what the two fields carry adds up to the
// light that arrived. 0 for light from behind the surface.
SHARED_FN float fresnelReflectance(float cosIncident, float ior) {
  if (!(cosIncident > 0.0f)) return 0.0f;
  return 1.0f - fresnelTransmittance(cosIncident, ior);
}

// Where the sun ray mirrored by the surface point (local, h) meets a horizontal layer `height`
// metres above the mean level (xy), and its Fresnel reflectance relative to flat water's (z).
// A ray that cannot rise (the back of a wave, or mirrored downward by a steep face) carries no
// light: z = 0. A layer below the crest it left from is met at the crest (path 0).
SHARED_FN vec3 reflectToLayer(vec2 local, vec3 surface, vec3 towardSun, float ior,
                              float invFlatReflectance, float height) {
  vec3 n = waterNormalFromSlopes(vec2(surface.x, surface.y));
  float h = sanitizeHeight(surface.z);
  float cosIncident = dot(towardSun, n);
  vec3 r = reflect(-towardSun, n);
  if (!(cosIncident > 0.0f) || !(r.y > 1e-4f)) return vec3(local, 0.0f);
  float path = max((height - h) / r.y, 0.0f);
  float weight = fresnelReflectance(cosIncident, ior) * invFlatReflectance;
  return vec3(local + vec2(r.x, r.z) * path, weight);
}

// Where a layer `layerHeight` above the level is looked up for a receiver at xz, `height` above
// it: the point its flat-water mirror ray (rising along (-sun.x, sun.y, -sun.z)) reaches at the
// layer's height. rise = -towardSun.xz / towardSun.y, the mirror ray's drift per metre of height.
SHARED_FN vec2 reflectedLayerSamplePoint(vec2 xz, float height, float layerHeight, vec2 rise) {
  return xz + rise * (layerHeight - height);
}

// How much of the pattern a receiver `height` above the level keeps: 1 up to the highest layer,
// fading to 0 (the mean) over REFLECTED_TOP_FADE of maxHeight above it.
SHARED_FN float reflectedTopWeight(float height, float maxHeight) {
  float t = (height - maxHeight) / max(REFLECTED_TOP_FADE * maxHeight, 1e-6f);
  return 1.0f - clamp(t, 0.0f, 1.0f);
}

SHARED_END

#endif
