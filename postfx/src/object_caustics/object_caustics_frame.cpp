#include "object_caustics/object_caustics_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gbuffer/codec.h>

#include "core/convention_checks.h"

#include "core/block_check.h"
#include "core/frame_geometry.h"
#include "core/shared_math.h"

namespace postfx::detail {

void lightAxes(const glm::dvec3& d, glm::dvec3& right, glm::dvec3& up) {
  const glm::dvec3 reference =
      std::abs(d.z) < 0.9 ? glm::dvec3(0.0, 0.0, 1.0) : glm::dvec3(1.0, 0.0, 0.0);
  right = glm::normalize(glm::cross(reference, d));
  up = glm::cross(d, right);
}

namespace {

glm::dvec3 corner(const glm::vec3& lo, const glm::vec3& hi, int i) {
  return glm::dvec3((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
}

bool underwaterCasters(const FrameDesc& frame, std::uint64_t casters) {
  glm::dvec3 lo, hi;
  casterWorldBounds(frame.objectCaustics, lo, hi, casters);
  return 0.5 * (lo.y + hi.y) < frame.water.level;
}

// Anchor-relative world -> the sun's orthographic clip over a square of half side `half`
// (m), z in [0, 1] over the casters' depth (clip control set by the pass).
glm::dmat4 sunClip(const ObjectLightFrame& f, double half) {
  glm::dmat4 clip(0.0);
  for (int i = 0; i < 3; ++i) {
    clip[i][0] = f.right[i] / half;
    clip[i][1] = f.up[i] / half;
    clip[i][2] = f.direction[i] / (f.zFar - f.zNear);
  }
  clip[3][2] = -f.zNear / (f.zFar - f.zNear);
  clip[3][3] = 1.0;
  return clip;
}

// Anchor-relative world -> a local light's perspective clip along its axis, a square frustum of
// half side `tanHalf` at unit distance, window z in [0, 1] from zNear to zFar.
glm::dmat4 localLightClip(const ObjectLightFrame& f, double tanHalf) {
  const glm::dvec3 eye = f.position - f.anchor;
  glm::dmat4 view(1.0);
  for (int i = 0; i < 3; ++i) {
    view[i][0] = f.right[i];
    view[i][1] = f.up[i];
    view[i][2] = f.direction[i];
  }
  view[3] =
      glm::dvec4(-glm::dot(f.right, eye), -glm::dot(f.up, eye), -glm::dot(f.direction, eye), 1.0);
  glm::dmat4 projection(0.0);
  projection[0][0] = projection[1][1] = 1.0 / tanHalf;
  projection[2][2] = f.zFar / (f.zFar - f.zNear);
  projection[3][2] = -f.zFar * f.zNear / (f.zFar - f.zNear);
  projection[2][3] = 1.0;
  return projection * view;
}

}  // namespace

bool localLightUnderwater(const FrameDesc& frame, const LocalLight& light) {
  return light.position.y <= frame.water.level;
}

glm::dvec3 casterWorldCorner(const CasterMesh& mesh, int i) {
  return glm::dvec3(mesh.modelToWorld * glm::dvec4(corner(mesh.boundsMin, mesh.boundsMax, i), 1.0));
}

void casterWorldBounds(const ObjectCausticsFrame& objects, glm::dvec3& lo, glm::dvec3& hi,
                       std::uint64_t casters) {
  lo = glm::dvec3(std::numeric_limits<double>::max());
  hi = -lo;
  for (int c = 0; c < objects.casterCount; ++c) {
    if (!((casters >> c) & 1u)) continue;
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 p = casterWorldCorner(objects.casters[c], i);
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
}

glm::mat4 casterModelToAnchor(const ObjectLightFrame& light, const CasterMesh& mesh) {
  glm::dmat4 fromWorld(1.0);
  fromWorld[3] = glm::dvec4(-light.anchor, 1.0);
  return saturatedFloat(fromWorld * mesh.modelToWorld);
}

glm::mat4 casterNormalToWorld(const CasterMesh& mesh) {
  return glm::mat4(saturatedFloat(glm::transpose(glm::inverse(glm::dmat3(mesh.modelToWorld)))));
}

bool casterMatricesFinite(const FrameDesc& frame, const ObjectLightFrame& light) {
  const ObjectCausticsFrame& objects = frame.objectCaustics;
  for (int c = 0; c < objects.casterCount; ++c) {
    const glm::mat4 matrices[2] = {casterModelToAnchor(light, objects.casters[c]),
                                   casterNormalToWorld(objects.casters[c])};
    for (const glm::mat4& m : matrices)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          if (!std::isfinite(m[i][j])) return false;
  }
  return true;
}

bool castersInReceiverView(const ObjectCausticsFrame& objects) {
  return castersInReceiverView(objects, objects.receivers, ~std::uint64_t(0));
}

bool castersInReceiverView(const ObjectCausticsFrame& objects, const SunShadowMap& receivers,
                           std::uint64_t casters) {
  glm::dvec3 lo, hi;
  casterWorldBounds(objects, lo, hi, casters);
  // Bounds that overflow under their transform cannot be fitted: nothing sensible to draw.
  const glm::dvec3 extent = hi - lo;
  if (!(std::isfinite(extent.x) && std::isfinite(extent.y) && std::isfinite(extent.z)))
    return false;
  glm::dvec2 ndcLo(std::numeric_limits<double>::max()), ndcHi(-ndcLo);
  bool any = false;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const glm::dvec4 clip = receivers.worldToLightClip * glm::dvec4(p, 1.0);
    if (!(clip.w > 0.0)) continue;
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    ndcLo = glm::min(ndcLo, ndc);
    ndcHi = glm::max(ndcHi, ndc);
    any = true;
  }
  return any && ndcHi.x >= -1.0 && ndcLo.x <= 1.0 && ndcHi.y >= -1.0 && ndcLo.y <= 1.0;
}

namespace {

// The casters whose bounds reach the sun's receiver map: only they light what it sees, and one
// far from them would stretch the sun's map over empty water (coarser texels for every caster).
// All of them when none does (the pass then draws nothing).
std::uint64_t castersOverReceivers(const ObjectCausticsFrame& objects) {
  std::uint64_t mask = 0;
  for (int c = 0; c < objects.casterCount && c < kMaxCasters; ++c) {
    const std::uint64_t bit = std::uint64_t(1) << c;
    if (castersInReceiverView(objects, objects.receivers, bit)) mask |= bit;
  }
  return mask != 0 ? mask : ~std::uint64_t(0);
}

}  // namespace

ObjectLightFrame fitObjectLightFrame(const FrameDesc& frame) {
  ObjectLightFrame f;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const std::uint64_t casters = castersOverReceivers(frame.objectCaustics);
  f.underwater = underwaterCasters(frame, casters);
  f.outerIor = f.underwater ? double(frame.water.ior) : 1.0;
  f.direction = f.underwater ? glm::normalize(refractedSunDown(sun, frame.water.ior)) : -sun;
  lightAxes(f.direction, f.right, f.up);

  glm::dvec3 lo, hi;
  casterWorldBounds(frame.objectCaustics, lo, hi, casters);
  glm::dvec3 llo(std::numeric_limits<double>::max()), lhi(-llo);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 p((i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z);
    const glm::dvec3 l(glm::dot(p, f.right), glm::dot(p, f.up), glm::dot(p, f.direction));
    llo = glm::min(llo, l);
    lhi = glm::max(lhi, l);
  }
  const ObjectCausticsSettings& s = frame.objectCaustics.settings;
  // 2% room so that silhouettes are not cut by the map's edge.
  const double side = std::max({lhi.x - llo.x, lhi.y - llo.y, 1e-6}) * 1.02;
  const double quantised = std::exp2(std::ceil(std::log2(side) * 8.0) / 8.0);
  f.halfGrid = 0.5 * quantised;
  f.halfMap = f.halfGrid * double(s.footprintScale);
  const double cell = quantised / double(s.gridSize);
  const double cu = std::round(0.5 * (llo.x + lhi.x) / cell) * cell;
  const double cv = std::round(0.5 * (llo.y + lhi.y) / cell) * cell;
  const double cz = 0.5 * (llo.z + lhi.z);
  f.anchor = cu * f.right + cv * f.up + cz * f.direction;
  const double depthRoom = 0.01 * (lhi.z - llo.z) + 1e-4;
  f.zNear = llo.z - cz - depthRoom;
  f.zFar = lhi.z - cz + depthRoom;
  return f;
}

bool volumeCausticsOn(const CreateDesc& create, const FrameDesc& frame) {
  const glm::vec3 scattering = frame.water.scattering;
  return hasFeature(create.features, Feature::VolumeCaustics) &&
         frame.objectCaustics.settings.volume.enabled && frame.godRays.intensity > 0.0f &&
         std::max({scattering.r, scattering.g, scattering.b}) > 0.0f &&
         frame.viewExtinction == ViewExtinction::Plugin;
}

namespace {

// The volume caustics' constants (postfx_object_caustics_block.h): the god rays' scattering,
// phase, fades and reach, and what a ray's grid cell measures.
void fillVolumeConstants(const FrameDesc& frame, const ObjectLightFrame& f, int height,
                         shared::ObjectCausticsBlock& b) {
  const ObjectCausticsFrame& objects = frame.objectCaustics;
  const ObjectCausticsSettings& s = objects.settings;
  const GodRaySettings& g = frame.godRays;
  const LocalLight* light = f.local() ? &objects.lights[f.light] : nullptr;
  const glm::dvec3 scale =
      light != nullptr ? glm::dvec3(light->intensity) : glm::dvec3(frame.sun.irradiance);
  const double cell = 2.0 * (light ? f.tanHalfGrid : f.halfGrid) / s.gridSize;
  b.volumeLight =
      glm::vec4(glm::vec3(glm::dvec3(frame.water.scattering) * double(g.intensity) * scale),
                float(cell * cell));
  const double cosT = std::max(-f.direction.y, 1e-3);
  b.volumeExtinction = glm::vec4(frame.water.absorption + frame.water.scattering,
                                 light == nullptr && f.underwater ? float(1.0 / cosT) : 0.0f);
  b.volumeFade = glm::vec4(g.surfaceFadeDistance, g.depthFadeDistance, g.maxDistance, 1.0f);
  const double focal = std::abs(frame.camera.projection[1][1]);
  b.volumePixel =
      glm::vec4(float(2.0 / (focal * double(height))),
                s.volume.method == VolumeCausticsMethod::Lines ? 1.0f : 0.0f, 0.0f, 0.0f);
}

}  // namespace

shared::ObjectCausticsBlock buildObjectCausticsBlock(const CreateDesc& create,
                                                     const FrameDesc& frame,
                                                     const ObjectLightFrame& f, int width,
                                                     int height) {
  shared::ObjectCausticsBlock b{};
  const ObjectCausticsFrame& objects = frame.objectCaustics;
  const ObjectCausticsSettings& s = objects.settings;
  const LocalLight* light = f.local() ? &objects.lights[f.light] : nullptr;
  const SunShadowMap& receivers = light != nullptr ? light->receivers : objects.receivers;
  if (light != nullptr) {
    b.casterClip = glm::mat4(localLightClip(f, f.tanHalfGrid));
    b.mapClip = glm::mat4(localLightClip(f, f.tanHalfMap));
  } else {
    b.casterClip = glm::mat4(sunClip(f, f.halfGrid));
    b.mapClip = glm::mat4(sunClip(f, f.halfMap));
  }
  glm::dmat4 toAnchor(1.0);
  toAnchor[3] = glm::dvec4(f.anchor, 1.0);
  const glm::dmat4 receiverClip = receivers.worldToLightClip * toAnchor;
  b.receiverClip = saturatedFloat(receiverClip);
  b.receiverClipInverse = saturatedFloat(glm::inverse(receiverClip));
  b.viewToWorld = glm::mat4(glm::mat3(viewToWorldRotation(frame.camera.view)));

  b.lightDir = glm::vec4(glm::vec3(f.direction), float(s.iterations));
  b.lightRight = glm::vec4(glm::vec3(f.right), float(f.halfGrid));
  b.lightUp = glm::vec4(glm::vec3(f.up), float(f.halfMap));
  // Each ray carries the sun's flux through one grid cell; the map stores flux per texel area
  // (both perpendicular to the light): irradiance relative to the sun's. A local light's cells
  // and texels are measured at unit distance on its view's plane (the trace adds the solid
  // angles' cos^3 and the inverse square: localLightShare).
  const double cell = 2.0 * (light ? f.tanHalfGrid : f.halfGrid) / s.gridSize;
  const double texel = 2.0 * (light ? f.tanHalfMap : f.halfMap) / s.mapSize;
  b.grid = glm::vec4(float(s.gridSize), float(s.mapSize), s.splatRadius,
                     float((cell * cell) / (texel * texel)));
  const DepthConvention conv = receivers.depthConvention;
  b.receiver = glm::vec4(conv == DepthConvention::ForwardNegOneToOne ? 1.0f : 0.0f,
                         conv == DepthConvention::ReverseZ ? 0.0f : 1.0f, receivers.bias, 0.0f);
  const glm::dvec3 cameraOffset = frame.camera.position - f.anchor;
  b.cameraOffset = glm::vec4(glm::vec3(cameraOffset), float(frame.water.level - f.anchor.y));
  b.viewport = glm::vec4(1.0f / float(width), 1.0f / float(height), float(width), float(height));
  const gbuffer::ProjectionParams params =
      gbuffer::projectionParams(frame.camera.projection, toGbuffer(create.depthConvention));
  b.projection = params.xy;
  b.depthParams = glm::vec4(params.z, f.underwater ? 1.0f : 0.0f, float(s.exitIterations));
  if (light != nullptr) {
    b.lightScale = glm::vec4(light->intensity * s.intensity, 0.0f);
    b.lightPosition = glm::vec4(glm::vec3(light->position - f.anchor), 1.0f);
    if (light->type == LocalLightType::Spot) {
      const double half = glm::radians(double(light->coneAngleDegrees)) * 0.5;
      b.spotAxis = glm::vec4(glm::vec3(glm::normalize(light->direction)), 1.0f);
      b.spotCone.x = float(half);
      b.spotCone.y = float(half * (1.0 - double(light->coneSoftness)));
    }
    b.spotCone.z = localLightUnderwater(frame, *light) ? 1.0f : 0.0f;
    b.lightWater = glm::vec4(frame.water.absorption, 0.0f);
    // Texels per metre at the casters' distance: a rough caster's spread (casters.h) is
    // measured there (the casters are small next to their distance from the light).
    const double distance = std::max(glm::length(light->position - f.anchor), 1e-6);
    b.splatScale = glm::vec4(float(1.0 / (texel * distance)), kMaxRoughSplatSigma, 0.0f, 0.0f);
  } else {
    b.lightScale = glm::vec4(frame.sun.irradiance * s.intensity, 0.0f);
    // Same water-column model as the seabed caustics: Beer-Lambert along the refracted sun.
    const double cosT = std::max(-f.direction.y, 1e-3);
    b.waterAbsorption = glm::vec4(glm::dvec3(frame.water.absorption) / cosT, 0.0);
    b.splatScale = glm::vec4(float(1.0 / texel), kMaxRoughSplatSigma, 0.0f, 0.0f);
  }
  if (volumeCausticsOn(create, frame)) fillVolumeConstants(frame, f, height, b);
  const bool dispersion = hasFeature(create.features, Feature::Dispersion);
  if (frame.viewExtinction == ViewExtinction::Plugin)
    b.viewExtinction = glm::vec4(frame.water.absorption + frame.water.scattering, 0.0f);
  for (int c = 0; c < objects.casterCount && c < POSTFX_MAX_CASTERS; ++c) {
    const CasterMaterial& m = objects.casters[c].material;
    const bool reflective = m.type == CasterMaterialType::Reflective;
    // KHR_materials_dispersion's half spread, made relative to the outer medium like the IOR.
    const double spread =
        dispersion && !reflective ? (double(m.ior) - 1.0) * 0.025 * double(m.dispersion) : 0.0;
    if (spread > 0.0) b.receiver.w = 1.0f;
    glm::vec4* slot = &b.materials[POSTFX_CASTER_VEC4S * c];
    slot[0] = glm::vec4(reflective ? 1.0f : 0.0f, float(double(m.ior) / f.outerIor),
                        float(spread / f.outerIor), m.transmission);
    slot[1] = glm::vec4(reflective ? m.reflectance : m.absorption, m.roughness * m.roughness);
    slot[2] = glm::vec4(m.tint, m.thinWalled ? 1.0f : 0.0f);
  }
  return b;
}

glm::dmat4 localLightMapClip(const ObjectLightFrame& f) {
  glm::dmat4 fromWorld(1.0);
  fromWorld[3] = glm::dvec4(-f.anchor, 1.0);
  return localLightClip(f, f.tanHalfMap) * fromWorld;
}

ObjectCausticMap describeObjectCausticMap(const ObjectLightFrame& f, int mapSize) {
  ObjectCausticMap map;
  map.size = mapSize;
  map.axisU = f.right * (2.0 * f.halfMap);
  map.axisV = f.up * (2.0 * f.halfMap);
  map.origin = f.anchor - f.right * f.halfMap - f.up * f.halfMap;
  map.direction = f.direction;
  return map;
}

}  // namespace postfx::detail
