// One light ray per caster-map cell ([2], section III.C): refract at the front surface,
// find the back surface in image space and refract out (Wyman's double refraction), or reflect
// for metal; find the receiver in image space (eq. 1-4, secant steps with a bracketed fallback)
// and say where it lands in the caustic map and with what flux. Included by the trace pass,
// which runs it once per ray; the splat pass reads its results.
#ifndef POSTFX_OBJECT_CAUSTICS_TRACE_GLSL
#define POSTFX_OBJECT_CAUSTICS_TRACE_GLSL
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "shared/gbuffer_codec.h"
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

#include "postfx/object_caustics/object_caustics_light.glsl"

layout(binding = POSTFX_OBJECT_UNIT_FRONT_POSITION) uniform sampler2D frontPosition;
layout(binding = POSTFX_OBJECT_UNIT_FRONT_NORMAL) uniform sampler2D frontNormal;
layout(binding = POSTFX_OBJECT_UNIT_BACK_POSITION) uniform sampler2D backPosition;
layout(binding = POSTFX_OBJECT_UNIT_BACK_NORMAL) uniform sampler2D backNormal;
layout(binding = POSTFX_OBJECT_UNIT_SPLAT_RECEIVER_DEPTH) uniform sampler2D receiverDepth;

const float kNoBracket = 1e30;

// Light-space (u, v) of p, in [0, 1] over the grid region (outside it behind a local light).
vec2 gridUv(vec3 p) {
  vec2 uv;
  viewUv(u.casterClip, p, uv);
  return uv;
}

// The back surface where the light ray through p leaves the casters: bilinear over the covered
// texels only (a silhouette texel must not pull positions towards 0).
bool backSurface(vec3 p, out vec3 position, out vec3 normal) {
  int size = int(u.grid.x);
  vec2 t = gridUv(p) * u.grid.x - 0.5;
  ivec2 base = ivec2(floor(t));
  vec2 f = t - floor(t);
  vec4 sumPosition = vec4(0.0);
  vec3 sumNormal = vec3(0.0);
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 2; ++i) {
      ivec2 texel = base + ivec2(i, j);
      if (any(lessThan(texel, ivec2(0))) || any(greaterThanEqual(texel, ivec2(size)))) continue;
      vec4 q = texelFetch(backPosition, texel, 0);
      if (!(q.w > 0.5)) continue;
      float w = (i == 0 ? 1.0 - f.x : f.x) * (j == 0 ? 1.0 - f.y : f.y);
      sumPosition += vec4(q.xyz, 1.0) * w;
      sumNormal += texelFetch(backNormal, texel, 0).xyz * w;
    }
  }
  if (!(sumPosition.w > 1e-4)) return false;
  position = sumPosition.xyz / sumPosition.w;
  normal = safeNormalize(sumNormal);
  return dot(normal, normal) > 0.5;
}

// The receiver point on the light ray through p, read from the host's receiver depth map.
bool receiverSurface(vec3 p, out vec3 position) {
  vec4 clip = u.receiverClip * vec4(p, 1.0);
  if (!(clip.w > 0.0)) return false;
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  if (!(all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))))) return false;
  float depth = textureLod(receiverDepth, uv, 0.0).r;
  if (!(abs(depth - u.receiver.y) > 1e-6)) return false;  // cleared: no receiver there
  float ndcZ = u.receiver.x > 0.5 ? depth * 2.0 - 1.0 : depth;
  vec4 q = u.receiverClipInverse * vec4(ndc.xy, ndcZ, 1.0);
  if (!(abs(q.w) > 1e-20)) return false;
  position = q.xyz / q.w;
  return true;
}

// The image-space root search of [2] (eq. 1-4) along origin + d * ray against a surface
// seen from the light (the back faces, or the receivers). g(d) = (probe - S(probe)) . L is the
// probe's signed distance behind the surface along the light (< 0: not there yet). The paper's
// step d <- |S(probe) - origin| converges only linearly for a ray far from the light's direction:
// one step left the rim rays of a glass sphere up to half a radius short of the floor, so the
// step is the secant through the last two probes (the origin is the first, g known), exact in
// one step on a flat receiver, with the paper's step where the secant degenerates. It is taken
// while it stays inside the bracket [lo, hi] that the signs of g give and keeps contracting;
// otherwise (the oscillation [2] III.D describes) a bracketed step replaces it: false
// position, or bisection when that degenerates.
float nextDistance(float d, float g, float seedNext, bool secantStep, inout vec4 bracket,
                   inout float lastStep, inout vec2 previous) {
  // bracket = (lo, g(lo), hi, g(hi)); hi = kNoBracket while no probe has passed the surface.
  if (g < 0.0) {
    if (d >= bracket.x) bracket.xy = vec2(d, g);
  } else if (d <= bracket.z) {
    bracket.zw = vec2(d, g);
  }
  float slope = (g - previous.y) / (d - previous.x);
  float secant = d - g / slope;
  // A flat slope (probe and previous equally far from the surface) or a step backwards past the
  // origin means the secant knows nothing here: the paper's step does.
  bool useSecant = secantStep && abs(slope) > 1e-6 && secant > 0.0 && secant < 1e30;
  float candidate = useSecant ? secant : seedNext;
  previous = vec2(d, g);
  float step = abs(candidate - d);
  // A converged estimate sits on the bracket's end: only a real step may trigger the fallback.
  float tolerance = 1e-5 * (d + 1.0);
  bool outside = candidate < bracket.x - tolerance || candidate > bracket.z + tolerance;
  float next = candidate;
  if (bracket.z < kNoBracket && step > tolerance && (outside || step >= lastStep)) {
    float span = bracket.w - bracket.y;  // > 0: g(lo) < 0 <= g(hi)
    float falsePosition = bracket.x - bracket.y * (bracket.z - bracket.x) / max(span, 1e-30);
    bool inside = falsePosition > bracket.x && falsePosition < bracket.z;
    next = inside ? falsePosition : 0.5 * (bracket.x + bracket.z);
  }
  lastStep = abs(next - d);
  return next;
}

// Where the ray leaves the casters through the back surface. False: no back surface under the
// ray (a single-sided sheet): the caller exits at the entry point.
bool hitBack(vec3 origin, vec3 ray, int iterations, out vec3 exitPoint, out vec3 exitNormal) {
  vec3 surface, normal;
  if (!backSurface(origin, surface, normal)) return false;
  float d = length(surface - origin), lastStep = kNoBracket;
  float gOrigin = dot(origin - surface, lightRayAt(origin));
  vec4 bracket = vec4(0.0, gOrigin, kNoBracket, kNoBracket);
  vec2 previous = vec2(0.0, gOrigin);
  for (int k = 0; k < iterations; ++k) {
    vec3 probe = origin + d * ray;
    vec3 s, n;
    if (!backSurface(probe, s, n)) break;  // left the footprint: keep the estimate
    d = nextDistance(d, dot(probe - s, lightRayAt(probe)), length(s - origin), false, bracket,
                     lastStep, previous);
  }
  if (backSurface(origin + d * ray, surface, normal)) {
    exitPoint = surface;
    exitNormal = normal;
  } else {
    exitPoint = origin + d * ray;
    exitNormal = lightRayAt(exitPoint);
  }
  return true;
}

bool hitReceiver(vec3 origin, vec3 ray, int iterations, out vec3 hit) {
  vec3 surface;
  if (!receiverSurface(origin, surface)) return false;
  float gOrigin = dot(origin - surface, lightRayAt(origin));
  float d = length(surface - origin), lastStep = kNoBracket;
  vec4 bracket = vec4(0.0, gOrigin, kNoBracket, kNoBracket);
  vec2 previous = vec2(0.0, gOrigin);
  for (int k = 0; k < iterations; ++k) {
    vec3 probe = origin + d * ray;
    if (!receiverSurface(probe, surface)) return false;  // left the receivers
    d = nextDistance(d, dot(probe - surface, lightRayAt(probe)), length(surface - origin), true,
                     bracket, lastStep, previous);
  }
  vec3 probe = origin + d * ray;
  if (!receiverSurface(probe, hit)) return false;
  // A ray that never meets the receivers (sent up and away) still gets an estimate, but its
  // probe ends farther in front of them than the ray's origin was: it moved away.
  return dot(probe - hit, lightRayAt(probe)) >= gOrigin;
}

// The colour channel a ray carries: all three (channel 0, one ray per cell), or, when a caster
// is dispersed (every cell traced three times), that channel with its own IOR. Returns false
// for the rays a non-dispersed caster does not need when another caster is dispersed.
bool rayChannel(int channel, float spread, out vec3 mask, out float etaOffset) {
  mask = vec3(1.0);
  etaOffset = 0.0;
  if (!(u.receiver.w > 0.5)) return true;
  if (!(spread > 0.0)) return channel == 0;
  mask = vec3(equal(ivec3(0, 1, 2), ivec3(channel)));
  etaOffset = float(channel - 1) * spread;  // R: -h, G: 0, B: +h (red bends least)
  return true;
}

// A local light's way to where a ray enters the caster: its unit direction (l), length, the
// cosine off the view's axis, the spot's cone and how much of it lies under the water. Computed
// once per ray for both what lands (localLightShare) and what scatters (segmentPower).
struct LightPath {
  bool valid;  // false for the sun, or a ray entering at the light itself
  vec3 l;
  float distance, cosRay, cone, wet;
};

LightPath lightPathTo(vec3 entry) {
  LightPath p = LightPath(false, vec3(0.0), 0.0, 0.0, 0.0, 0.0);
  if (!localLight()) return p;
  vec3 light = u.lightPosition.xyz;
  vec3 toEntry = entry - light;
  p.distance = length(toEntry);
  if (!(p.distance > 1e-9)) return p;
  p.valid = true;
  p.l = toEntry / p.distance;
  p.cosRay = dot(p.l, u.lightDir.xyz);
  p.cone = 1.0;
  if (u.spotAxis.w > 0.5)
    p.cone = spotConeFalloff(acos(clamp(dot(p.l, u.spotAxis.xyz), -1.0, 1.0)), u.spotCone.x,
                             u.spotCone.y);
  float level = u.cameraOffset.w;  // water level, anchor-relative
  p.wet = submergedLength(p.distance, light.y - level, entry.y - level);
  return p;
}

// What a local light's ray carries relative to the sun's normalisation (u.grid.w, the ray's
// cell over a map texel), from where it enters the caster to where it lands: the cell's solid
// angle over that of the map texel it lands in (cos^3 off the view's axis for each), the inverse
// square of the distance it lands at (the map holds irradiance per unit intensity, on a surface
// facing the light), the spot's cone, and Beer-Lambert along its path under water outside the
// caster. 0 where that is undefined (a landing at the light or beside its view).
vec3 localLightShare(LightPath path, vec3 exitPoint, vec3 hit) {
  if (!localLight()) return vec3(1.0);
  vec3 toHit = hit - u.lightPosition.xyz;
  float hitDistance2 = dot(toHit, toHit);
  if (!(path.valid && hitDistance2 > 1e-18)) return vec3(0.0);
  float cosHit = dot(toHit, u.lightDir.xyz) * inversesqrt(hitDistance2);
  if (!(cosHit > 1e-4)) return vec3(0.0);
  float ratio = path.cosRay / cosHit;
  float level = u.cameraOffset.w;
  float wet =
      path.wet + submergedLength(length(hit - exitPoint), exitPoint.y - level, hit.y - level);
  return vec3(path.cone * ratio * ratio * ratio / hitDistance2) * exp(-u.lightWater.rgb * wet);
}

// A ray's straight way through the water from where it leaves the caster to where it lands,
// and the power it carries along it (the volume caustics'; anchor-relative metres).
struct RaySegment {
  vec3 start, end;
  vec3 power;  // u.volumeLight's units: the light's scale times sigma_s and phase, times m^2 or sr
};

// The power of a ray carrying `flux` (Fresnel, transmission, tint, the glass's absorption) of
// its cell, extinguished (sigma_t, as the god rays' sun path) from the water surface (the sun)
// or the light (`path`) to where it entered the caster at `entry`.
vec3 segmentPower(LightPath path, vec3 entry, vec3 flux) {
  if (!localLight()) {
    float depth = max(u.cameraOffset.w - entry.y, 0.0) * u.volumeExtinction.w;
    return flux * u.volumeLight.rgb * u.volumeLight.w * exp(-u.volumeExtinction.rgb * depth);
  }
  if (!path.valid) return vec3(0.0);
  // The cell's solid angle: the view's axial one times cos^3 off the axis.
  float cosRay = max(path.cosRay, 0.0);
  return flux * u.volumeLight.rgb * (u.volumeLight.w * cosRay * cosRay * cosRay * path.cone) *
         exp(-u.volumeExtinction.rgb * path.wet);
}

// One ray through a grid cell: where it lands (map texels), the flux it carries there and the
// splat width its roughness asks for (map texels), and its segment through the water. False:
// the cell misses the casters, the ray is lost (total internal reflection) or it meets no
// receiver.
bool traceCell(ivec2 cell, int channel, out vec2 centre, out vec3 rayFlux, out float sigma,
               out RaySegment segment) {
  centre = vec2(0.0);
  rayFlux = vec3(0.0);
  sigma = u.grid.z;
  segment = RaySegment(vec3(0.0), vec3(0.0), vec3(0.0));
  vec4 front = texelFetch(frontPosition, cell, 0);
  if (!(front.w > 0.5)) return false;
  int caster = clamp(int(front.w + 0.5) - 1, 0, POSTFX_MAX_CASTERS - 1);
  vec4 material = u.materials[POSTFX_CASTER_VEC4S * caster];
  vec4 optics = u.materials[POSTFX_CASTER_VEC4S * caster + 1];
  vec4 transmitTint = u.materials[POSTFX_CASTER_VEC4S * caster + 2];
  vec3 tint = optics.rgb;
  float alpha = optics.w;
  bool reflective = material.x > 0.5;
  vec3 channelMask;
  float etaOffset;
  if (!rayChannel(channel, reflective ? 0.0 : material.z, channelMask, etaOffset)) return false;
  vec3 l = lightRayAt(front.xyz);
  vec3 n0 = texelFetch(frontNormal, cell, 0).xyz;  // faces the light
  float cosI = clamp(-dot(l, n0), 0.0, 1.0);
  int iterations = int(u.lightDir.w);

  vec3 origin, ray, flux;
  if (reflective) {
    // Even a ray sent back towards the sun can land on a receiver the sun sees (in front of a
    // mirror); one that never does is caught by hitReceiver.
    ray = reflect(l, n0);
    origin = front.xyz;
    flux = fresnelSchlick(cosI, tint);
  } else if (transmitTint.w > 0.5) {
    // Thin-walled: two parallel interfaces a negligible distance apart. The ray leaves in its
    // own direction from where it entered, less both Fresnel reflections (equal by
    // reciprocity); no volume, so no absorption.
    float eta = material.y + etaOffset;
    float t = 1.0 - fresnelDielectric(cosI, eta);
    ray = l;
    origin = front.xyz;
    flux = vec3(t * t) * material.w * transmitTint.rgb;
  } else {
    float eta = material.y + etaOffset;  // object over outer medium
    vec3 inside = refract(l, n0, 1.0 / eta);
    float transmitted = 1.0 - fresnelDielectric(cosI, eta);
    vec3 exitPoint = front.xyz, exitNormal = -n0;
    hitBack(front.xyz, inside, int(u.depthParams.w), exitPoint, exitNormal);
    // exitNormal faces away from the light: the outward normal on the exit side.
    float cosExit = abs(dot(inside, exitNormal));
    ray = refract(inside, -exitNormal * sign(dot(inside, exitNormal) + 1e-20), eta);
    // Total internal reflection: this ray's light stays inside.
    if (!(dot(ray, ray) > 0.5)) return false;
    transmitted *= 1.0 - fresnelDielectric(cosExit, 1.0 / eta);
    float path = length(exitPoint - front.xyz);
    // Transmission weight and tint once per ray; Beer-Lambert along the traversed chord.
    flux = transmitted * material.w * transmitTint.rgb * exp(-tint * path);
    origin = exitPoint;
  }
  vec3 hit;
  vec2 uv;
  if (!hitReceiver(origin, ray, iterations, hit) || !viewUv(u.mapClip, hit, uv)) return false;
  LightPath path = lightPathTo(front.xyz);
  rayFlux = flux * channelMask * u.grid.w * localLightShare(path, origin, hit);
  segment = RaySegment(origin, hit, segmentPower(path, front.xyz, flux * channelMask));
  centre = uv * u.grid.y;
  // Roughness: the ray's light spreads over a cone of angular deviation alpha, as wide on the
  // receiver as alpha times the distance travelled (casters.h, CasterMaterial::roughness).
  float spreadTexels = alpha * length(hit - origin) * u.splatScale.x;
  sigma = sqrt(u.grid.z * u.grid.z + spreadTexels * spreadTexels);
  return true;
}

#endif
