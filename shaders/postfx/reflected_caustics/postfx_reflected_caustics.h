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

// The share of the light a facet (normal's height component ny) mirrors into a ray rising at
// sine ry that leaves the waves instead of meeting the next one: microfacet theory's V-cavity
// masking, min(1, 2 ny ry / cos(incidence)) (the mirrored ray makes the incidence angle with the
// normal). 1 for flat water and any ray well above the horizon, falling to 0 as it grazes. A
// wall weights the low rays by their drift (reflectedReceiverLight), so without it the light
// the next crest catches lit the walls near the water far too brightly (docs/measurements.md,
// "Reflected caustics").
SHARED_FN float reflectedEscape(float ny, float ry, float cosIncident) {
  return min(1.0f, 2.0f * ny * ry / max(cosIncident, 1e-6f));
}

// The sun ray mirrored by a surface of unit normal n: its direction (xyz) and the light it
// carries relative to flat water's mirror light (w): Fresnel reflectance over flat water's, times
// the share that escapes the waves (reflectedEscape). A ray that cannot rise (the back of a wave,
// or mirrored downward by a steep face) carries none: w = 0.
SHARED_FN vec4 mirroredSunRay(vec3 n, vec3 towardSun, float ior, float invFlatReflectance) {
  float cosIncident = dot(towardSun, n);
  vec3 r = reflect(-towardSun, n);
  if (!(cosIncident > 0.0f) || !(r.y > 1e-4f)) return vec4(r, 0.0f);
  float weight = fresnelReflectance(cosIncident, ior) * invFlatReflectance;
  weight *= reflectedEscape(n.y, r.y, cosIncident);
  return vec4(r, weight);
}

// Where `ray` (mirroredSunRay) from the surface point (local, height h) meets a horizontal layer
// `height` metres above the mean level (xy), and the light it carries (z). A ray carrying none
// stays at its point. A layer below the crest it left from is met at the crest (path 0).
SHARED_FN vec3 reflectToLayer(vec2 local, float h, vec4 ray, float height) {
  if (!(ray.w > 0.0f)) return vec3(local, 0.0f);
  float path = max((height - h) / ray.y, 0.0f);
  return vec3(local + vec2(ray.x, ray.z) * path, ray.w);
}

// The mirrored ray's horizontal drift per metre of rise, ray.xz / ray.y: what the field carries
// besides the light, so that a receiver of any orientation gets what the rays arriving at it
// deliver (reflectedReceiverLight). Rays that cannot rise get `flatRise`, so that nothing in
// them is undefined.
SHARED_FN vec2 mirroredDrift(vec4 ray, vec2 flatRise) {
  if (!(ray.y > 1e-4f)) return flatRise;
  return vec2(ray.x, ray.z) / ray.y;
}

// The light a receiver of unit normal n gets from the field (I, Dx, Dz): I the flux crossing a
// horizontal plane relative to flat water's, D the sum of that flux times each ray's drift d =
// ray.xz / ray.y. A ray of horizontal flux f meets a face of normal n with f (-n.y - n.xz . d)
// per unit area, linear in d, so the sum over every ray crossing there is exactly
// -n.y I - n.xz . D: a wall facing the sea weights the low rays (large d) as much more as they
// deserve, an underside weights all alike. Scaled by sun.y to flat water's n . l_r (flat: D =
// I rise, rise = -sun.xz / sun.y), never negative (rays from behind the face) nor above
// `maxLight` (the clamp, in flat water's light on a face turned to the mirrored sun: a face
// can gather more than the horizontal clamp lets through, from low rays), less `subtract` times
// flat water's light (0: the whole light; 1: the waves' modulation alone, signed; a host's own
// flat mirror light in the shade, or on a face turned from the flat mirror ray, is 0, so is then
// what is subtracted).
SHARED_FN float reflectedReceiverLight(vec3 n, vec3 field, float sunY, vec2 rise, float subtract,
                                       float maxLight) {
  float light = sunY * (-n.y * field.x - n.x * field.y - n.z * field.z);
  float flatLight = max(sunY * (-n.y - n.x * rise.x - n.z * rise.y), 0.0f);
  return clamp(light, 0.0f, maxLight) - subtract * flatLight;
}

// The mean drift per metre of rise of the rays in a field sample (light, drift sums): D / I where
// enough light arrives to say, flat water's `rise` where almost none does (its ratio is then
// noise).
SHARED_FN vec2 reflectedMeanDrift(vec3 field, vec2 rise) {
  float trust = smoothstep(0.02f, 0.1f, field.x);
  return rise + (vec2(field.y, field.z) / max(field.x, 1e-6f) - rise) * trust;
}

// Where a layer `layerHeight` above the level is looked up for a receiver at xz, `height` above
// it: the point a ray of horizontal drift `rise` per metre of height through the receiver meets
// at the layer's height (flat water's mirror ray: -towardSun.xz / towardSun.y; or the mean ray
// arriving there, reflectedMeanDrift).
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
