#version 450 core
// Reflected caustics landing on the view's depth (ReflectedLanding::ViewDepth), step 1 of 3:
// every water grid point's mirrored sun ray (reflected_light_vertices.comp's, the sun's shadow
// on the water included) followed through the view's G-buffer depth to the first receiver it
// meets. Writes two vec4s per point: (camera-relative hit position (m), the light the ray
// carries relative to flat water's mirror light; < 0: it meets no receiver in the view) and
// (the receiver's unit normal (the depth's own plane), the variance per axis (m^2) of where the
// rays the point stands for land about it: the sun's disc and the slopes finer than the grid's
// cells, each deviating the mirrored ray, over its path, stretched by the receiver's obliquity).
// Compile-time switches: POSTFX_WATER_SINGLE_2D, POSTFX_SHADOW_MASK, POSTFX_DEPTH_CONVENTION.
#include "shared/common.h"
#include "shared/gbuffer_codec.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/reflected_caustics/postfx_reflected_caustics.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"
#include "postfx/seabed_caustics/tile_irradiance_spread_statistics.glsl"

layout(local_size_x = 16, local_size_y = 16) in;

#include "postfx/seabed_caustics/grid_water.glsl"
layout(binding = POSTFX_UNIT_DEPTH) uniform sampler2D gbufferDepth;

// xy: camera-relative world xz of grid point (0, 0) (m); z: grid spacing (m); w: the level
// relative to the camera (m).
layout(location = 5) uniform vec4 grid;
layout(location = 6) uniform vec4 towardSun;  // xyz: unit vector to the sun; w: IOR
// x: 1 / flat-water reflectance; y: the highest receiver a ray is followed to (m above the
// level); z: the longest path followed (m)
layout(location = 7) uniform vec4 scales;
// x: the sun disc's angular variance per axis (rad^2; a uniform disc of radius a: a^2 / 4);
// y: 1 when the slopes inside the cells spread the light (CausticsSettings::tileUnresolvedSpread)
layout(location = 8) uniform vec2 spread;
layout(location = 9) uniform int pointsPerSide;

// Each cascade's slope moments inside the grid's cells (CellSlopeStatistics).
layout(std430, binding = POSTFX_STORAGE_TILE_SPREAD) readonly buffer TileSpread {
  TileSpreadPartial partials[];  // cascade * TILE_SPREAD_PARTS + part
};

// The covariance (xx, xz, zz) of the water's slopes inside a grid cell, every cascade's.
vec3 unresolvedSlopes() {
  vec3 slopes = vec3(0.0);
  for (int c = 0; c < POSTFX_MAX_CASCADES; ++c) {
    if (c >= cascadeCount) break;
    vec4 moments = vec4(0.0);
    for (int p = 0; p < TILE_SPREAD_PARTS; ++p)
      moments += partials[c * TILE_SPREAD_PARTS + p].cellMoments;
    slopes += moments.xyz / max(moments.w, 1.0);
  }
  return slopes;
}

// The angular variance per axis (rad^2) of a ray mirrored by normal n from the sun, for slopes
// of covariance s about n's: a slope step turns the normal by n.y (I - n n^T) of it, and the
// mirror turns the ray by -2 ((l . dn) n + (l . n) dn).
float mirroredSlopeVariance(vec3 n, vec3 s) {
  vec3 l = -towardSun.xyz;
  vec3 dnx = n.y * (vec3(-1.0, 0.0, 0.0) + n * n.x);
  vec3 dnz = n.y * (vec3(0.0, 0.0, -1.0) + n * n.z);
  vec3 gx = -2.0 * (dot(l, dnx) * n + dot(l, n) * dnx);
  vec3 gz = -2.0 * (dot(l, dnz) * n + dot(l, n) * dnz);
  return 0.5 * (s.x * dot(gx, gx) + 2.0 * s.y * dot(gx, gz) + s.z * dot(gz, gz));
}

#if POSTFX_SHADOW_MASK
layout(binding = POSTFX_UNIT_SHADOW) uniform sampler2DShadow sunShadowMap;
#include "postfx/seabed_caustics/sun_visibility.glsl"
#endif

layout(std430, binding = POSTFX_STORAGE_GRID_POINTS) writeonly buffer GridPoints {
  vec4 gridPoints[];
};

// Screen samples along the ray (its projection split evenly) and bisection steps at a crossing.
const int kMarchSteps = 64;
const int kRefineSteps = 8;
// How far past the view's edge (pixels) a surface the edge cuts is taken on.
const float kPastEdge = 8.0;
// marchView's answer for a ray that meets no receiver in the view but leaves it (or never
// enters it): where its light lands is unknown, not nowhere.
const float kLeftView = -2.0;

// View-space position of the host's surface at view pixel `pixel` (its centre); z = 0 for the sky.
vec3 surfaceAt(ivec2 pixel) {
  float depth = texelFetch(gbufferDepth, pixel + ivec2(u.viewOrigin.xy), 0).r;
  if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) return vec3(0.0);
  return viewPositionFromDepth((vec2(pixel) + 0.5) * u.viewport.xy, depth, u.projection,
                               u.depthAndWater.xy, POSTFX_DEPTH_CONVENTION);
}

// View pixel coordinates of view-space point v (in front of the camera).
vec2 toPixels(vec3 v) {
  vec2 ndc = vec2(u.projection.x * v.x + u.projection.z * v.z,
                  u.projection.y * v.y + u.projection.w * v.z) / -v.z;
  return (ndc * 0.5 + 0.5) * u.viewport.zw;
}

ivec2 pixelOf(vec2 s) {
  return clamp(ivec2(floor(s)), ivec2(0), ivec2(u.viewport.zw) - 1);
}

// The unit normal (view space, toward the camera) of the host's depth at `pixel` whose position
// is `at`: from its neighbours, on each axis the side nearer in depth (not across an edge). The
// depth's own plane, not the G-buffer's shading normal: a normal map's bumps would scatter the
// hits of one flat wall off its plane and tear the triangles landing on it.
vec3 depthNormal(ivec2 pixel, vec3 at) {
  ivec2 last = ivec2(u.viewport.zw) - 1;
  vec3 xp = surfaceAt(min(pixel + ivec2(1, 0), last)) - at;
  vec3 xm = at - surfaceAt(max(pixel - ivec2(1, 0), ivec2(0)));
  vec3 yp = surfaceAt(min(pixel + ivec2(0, 1), last)) - at;
  vec3 ym = at - surfaceAt(max(pixel - ivec2(0, 1), ivec2(0)));
  // At the view's edge the outer side is the pixel itself: the inner one is taken.
  vec3 dx = pixel.x == 0 || (pixel.x < last.x && abs(xp.z) < abs(xm.z)) ? xp : xm;
  vec3 dy = pixel.y == 0 || (pixel.y < last.y && abs(yp.z) < abs(ym.z)) ? yp : ym;
  vec3 n = cross(dx, dy);
  if (!(dot(n, n) > 0.0)) return vec3(0.0);
  n = normalize(n);
  return dot(n, at) > 0.0 ? -n : n;
}

// Where the view-space ray va + dir f (f in [0, 1]) meets the plane of the host's surface at
// `pixel` (its position and depthNormal), if that point lies on the pixel (within the bisection's
// reach), or past the view's edge by under kPastEdge pixels beside it: a wall the frame cuts is
// taken on past the edge, so that the triangles straddling the edge land whole and the pixels
// along it keep their light. -1 otherwise (a ray passing behind a pillar meets the pillar's
// plane far from it).
float planeHit(vec3 va, vec3 dir, ivec2 pixel, out vec3 normal) {
  normal = vec3(0.0);
  vec3 at = surfaceAt(pixel);
  if (!(at.z < 0.0)) return -1.0;
  vec3 n = depthNormal(pixel, at);
  float facing = dot(dir, n);
  if (!(facing < 0.0)) return -1.0;
  float f = dot(at - va, n) / facing;
  vec2 onScreen = toPixels(va + dir * f);
  vec2 outside = max(max(-onScreen, onScreen - u.viewport.zw), vec2(0.0));
  float away = distance(onScreen, vec2(pixel) + 0.5);
  bool onPixel = all(lessThan(abs(onScreen - (vec2(pixel) + 0.5)), vec2(1.5)));
  bool pastEdge = max(outside.x, outside.y) > 0.0 && max(outside.x, outside.y) < kPastEdge &&
                  away < kPastEdge + 1.5;
  if (!(f >= 0.0 && f <= 1.0) || !(onPixel || pastEdge)) return -1.0;
  normal = n;
  return f;
}

// The first receiver the view-space ray a -> b meets in the host's depth: its parameter along
// a..b in [0, 1] and the view pixel it lies in, or -1. The ray is walked as a screen segment
// (1/distance linear along it) until it passes from in front of the depth to behind it; the
// crossing is bracketed to one pixel by bisection and the ray meets that pixel's surface plane
// (position and G-buffer normal): a hit only where that point lies on the pixel (a ray passing
// behind a pillar meets the pillar's plane far from it and walks on), and its position is the
// plane's, continuous from one ray to the next whatever the depth's precision.
float marchView(vec3 a, vec3 b, out vec3 hitNormal) {
  hitNormal = vec3(0.0);
  const float nearest = 0.01;  // in front of the camera only
  if (a.z > -nearest && b.z > -nearest) return kLeftView;
  float t0 = 0.0, t1 = 1.0;
  if (a.z > -nearest) t0 = (a.z + nearest) / (a.z - b.z);
  if (b.z > -nearest) t1 = (a.z + nearest) / (a.z - b.z);
  vec3 va = mix(a, b, t0), vb = mix(a, b, t1);
  vec2 sa = toPixels(va), sb = toPixels(vb);
  float ka = 1.0 / -va.z, kb = 1.0 / -vb.z;
  // Clip the screen segment s = sa + (sb - sa) q to the view (Liang-Barsky).
  vec2 d = sb - sa;
  float q0 = 0.0, q1 = 1.0;
  for (int axis = 0; axis < 2; ++axis) {
    float lo = -sa[axis], hi = u.viewport[2 + axis] - sa[axis];
    if (abs(d[axis]) < 1e-6) {
      if (lo > 0.0 || hi < 0.0) return kLeftView;
    } else {
      float e0 = lo / d[axis], e1 = hi / d[axis];
      q0 = max(q0, min(e0, e1));
      q1 = min(q1, max(e0, e1));
    }
  }
  if (!(q0 < q1)) return kLeftView;
  vec3 dir = vb - va;
  int steps = clamp(int(ceil(length(d) * (q1 - q0) / 1.5)), 2, kMarchSteps);
  float prevQ = q0;
  // A hit is a step from in front of the host's surface to behind it: a ray that starts hidden
  // (water behind a hull) is not taken for a hit on the hull's front until it has come out. One
  // that enters the view from beyond its edges (or the near plane) is taken as in front there:
  // it may meet a surface at its first step (the wall the frame's edge cuts).
  bool wasInFront = q0 > 0.0 || t0 > 0.0;
  for (int i = 0; i <= kMarchSteps; ++i) {
    if (i > steps) break;
    float q = mix(q0, q1, float(i) / float(steps));
    float surface = -surfaceAt(pixelOf(sa + d * q)).z;
    bool behind = surface > 0.0 && 1.0 / mix(ka, kb, q) >= surface;
    if (behind && wasInFront) {
      float lo = prevQ, hi = q;
      for (int j = 0; j < kRefineSteps; ++j) {
        float mid = 0.5 * (lo + hi);
        float sm = -surfaceAt(pixelOf(sa + d * mid)).z;
        if (sm > 0.0 && 1.0 / mix(ka, kb, mid) >= sm) hi = mid;
        else lo = mid;
      }
      float f = planeHit(va, dir, pixelOf(sa + d * hi), hitNormal);
      if (f >= 0.0) return mix(t0, t1, f);
    }
    prevQ = q;
    wasInFront = !behind;
  }
  // Out of the view still in front of the last surface it passed: that surface, which the
  // frame's edge cuts, is taken on past it (planeHit).
  if (wasInFront && q1 < 1.0) {
    float f = planeHit(va, dir, pixelOf(sa + d * q1), hitNormal);
    if (f >= 0.0) return mix(t0, t1, f);
  }
  return q1 < 1.0 || t1 < 1.0 ? kLeftView : -1.0;
}

void main() {
  ivec2 index = ivec2(gl_GlobalInvocationID.xy);
  if (index.x >= pointsPerSide || index.y >= pointsPerSide) return;
  vec3 surface = gridWater(index);
  vec3 n = waterNormalFromSlopes(surface.xy);
  float h = sanitizeHeight(surface.z);
  vec4 ray = mirroredSunRay(n, towardSun.xyz, towardSun.w, scales.x);
  vec2 local = grid.xy + vec2(index) * grid.z;
  vec3 water = vec3(local.x, grid.w + h, local.y);
  int i = 2 * (index.y * pointsPerSide + index.x);
  vec4 hit = vec4(water, -1.0);
  vec4 receiver = vec4(0.0, 1.0, 0.0, 0.0);
  if (ray.y > 1e-4) {
    float path = min((scales.y - h) / ray.y, scales.z);
    mat3 worldToView = transpose(mat3(u.viewToWorld));
    vec3 a = worldToView * water;
    vec3 b = worldToView * (water + ray.xyz * path);
    vec3 viewNormal;
    float t = path > 0.0 ? marchView(a, b, viewNormal) : -1.0;
    if (t == kLeftView) hit.w = kLeftView;
    if (t >= 0.0) {
      vec3 at = water + ray.xyz * (path * t);
      vec3 normal = mat3(u.viewToWorld) * viewNormal;
      // A receiver above the level facing the ray; anything else ends the ray unlit.
      if (at.y > grid.w && dot(normal, ray.xyz) < 0.0) {
        float light = ray.w;
#if POSTFX_SHADOW_MASK
        if (light > 0.0) light *= sunVisibility(water, n);
#endif
        hit = vec4(at, light);
        float angular = spread.x;
        if (spread.y > 0.0) angular += mirroredSlopeVariance(n, unresolvedSlopes());
        // Spread across the ray, stretched along the receiver by 1 / cos of its incidence on one
        // axis (the mean of the two axes' variances).
        float incidence = max(-dot(normal, ray.xyz), 0.25);
        float travelled = path * t;
        float stretch = 0.5 * (1.0 + 1.0 / (incidence * incidence));
        receiver = vec4(normal, travelled * travelled * angular * stretch);
      }
    }
  }
  gridPoints[i] = hit;
  gridPoints[i + 1] = receiver;
}
