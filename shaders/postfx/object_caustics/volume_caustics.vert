#version 450 core
// One primitive per traced ray (and colour channel: the instance) over the part of its segment
// that lies under the water and in front of the camera. Beams (POSTFX_VOLUME_LINES 0): a
// screen-space capsule around the segment as wide as 3 sigma of its Gaussian cross-section at
// each end (6 vertices, two triangles), the cross-section's axes from where the neighbouring
// cells' rays run (the nearer of the two along each grid axis, so that a neighbour across a
// silhouette or the edge of total internal reflection does not widen the beam). Lines
// (POSTFX_VOLUME_LINES 1): the segment's two ends, drawn as a one-pixel GL line.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"
#include "postfx/object_caustics/volume_caustics_common.glsl"

layout(binding = POSTFX_OBJECT_UNIT_LANDINGS) uniform sampler2DArray landings;

flat out vec3 beamStart;  // camera-relative (m), the clipped segment's first end
flat out vec3 beamEnd;
flat out vec3 beamPower;  // block's volumeLight units (see postfx_object_caustics_block.h)
flat out float beamLightPath;  // water path (m) from the unclipped start to beamStart
// Beams: the cross-section's two axis vectors (half the spacing to the neighbouring rays,
// perpendicular to the ray) at beamStart and at beamEnd; lines: unused.
flat out vec3 axisX0, axisY0, axisX1, axisY1;
// Lines: 1 / cos of the line's angle to its major screen axis (one fragment per major-axis step).
flat out float lineSlant;

const float kNearest = 1e-3;  // m in front of the camera: the segment is clipped there

void drop() {
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // every vertex the same: no area, nothing drawn
  beamStart = beamEnd = beamPower = vec3(0.0);
  beamLightPath = 0.0;
  axisX0 = axisY0 = axisX1 = axisY1 = vec3(0.0);
  lineSlant = 1.0;
}

bool segmentOf(ivec2 cell, int channel, out vec3 start, out vec3 end) {
  start = end = vec3(0.0);
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(int(u.grid.x)))))
    return false;
  int layer = segmentLayer(channel);
  vec4 s = texelFetch(landings, ivec3(cell, layer), 0);
  start = s.xyz - u.cameraOffset.xyz;
  end = texelFetch(landings, ivec3(cell, layer + 1), 0).xyz - u.cameraOffset.xyz;
  return s.w > 0.5;
}

#if !POSTFX_VOLUME_LINES
// Half the vector (perpendicular to the ray `dir`) from this ray to the nearer neighbour along
// `axis`, at the start and at the end; 0 without a neighbour.
void neighbourAxis(ivec2 cell, int channel, ivec2 axis, vec3 start, vec3 end, vec3 dir,
                   out vec3 atStart, out vec3 atEnd) {
  atStart = atEnd = vec3(0.0);
  float best = 3.0e38;
  for (int side = -1; side <= 1; side += 2) {
    vec3 s, e;
    if (!segmentOf(cell + side * axis, channel, s, e)) continue;
    vec3 a = s - start, b = e - end;
    a -= dir * dot(a, dir);
    b -= dir * dot(b, dir);
    float size = dot(a, a) + dot(b, b);
    if (size < best) {
      best = size;
      atStart = 0.5 * a;
      atEnd = 0.5 * b;
    }
  }
}
#endif

// Pixel position (relative to the view's lower-left corner) of a view-space point in front.
vec2 toPixels(vec3 v) {
  vec2 ndc = vec2(u.projection.x * v.x + u.projection.z * v.z,
                  u.projection.y * v.y + u.projection.w * v.z) / -v.z;
  return (ndc * 0.5 + 0.5) * u.viewport.zw;
}

vec4 pixelsToClip(vec2 pixels) {
  return vec4(pixels * u.viewport.xy * 2.0 - 1.0, 0.5, 1.0);
}

void main() {
  int size = int(u.grid.x);
#if POSTFX_VOLUME_LINES
  int ray = gl_VertexID / 2, corner = gl_VertexID % 2;
#else
  int ray = gl_VertexID / 6, corner = gl_VertexID % 6;
#endif
  ivec2 cell = ivec2(ray % size, ray / size);
  int channel = gl_InstanceID;
  vec3 start, end;
  if (!segmentOf(cell, channel, start, end)) {
    drop();
    return;
  }
  vec3 power = texelFetch(landings, ivec3(cell, segmentLayer(channel) + 2), 0).rgb;
  float len = length(end - start);
  if (!(len > 1e-6) || !(max(power.r, max(power.g, power.b)) > 0.0)) {
    drop();
    return;
  }
  vec3 dir = (end - start) / len;
  // Keep [f0, f1] of the segment: under the water level and in front of the camera.
  float f0 = 0.0, f1 = 1.0;
  float level = cameraRelativeLevel();
  float ya = start.y - level, yb = end.y - level;
  if (ya > 0.0 && yb > 0.0) {
    drop();
    return;
  }
  if (ya > 0.0) f0 = ya / (ya - yb);
  if (yb > 0.0) f1 = ya / (ya - yb);
  vec3 va = worldToView(start), vb = worldToView(end);
  float za = -va.z - kNearest, zb = -vb.z - kNearest;
  if (za < 0.0 && zb < 0.0) {
    drop();
    return;
  }
  if (za < 0.0) f0 = max(f0, za / (za - zb));
  if (zb < 0.0) f1 = min(f1, za / (za - zb));
  if (!(f1 > f0)) {
    drop();
    return;
  }
  beamStart = start + (end - start) * f0;
  beamEnd = start + (end - start) * f1;
  beamPower = power;
  // The light's water path before beamStart (the clipped part above the level is in air).
  beamLightPath = submergedLength(len * f0, ya, min(ya + (yb - ya) * f0, 0.0));
  vec2 p0 = toPixels(va + (vb - va) * f0), p1 = toPixels(va + (vb - va) * f1);
  vec2 along = p1 - p0;
  float screenLength = length(along);
  vec2 d = screenLength > 1e-6 ? along / screenLength : vec2(1.0, 0.0);
  lineSlant = 1.0 / max(abs(d.x), abs(d.y));
#if POSTFX_VOLUME_LINES
  axisX0 = axisY0 = axisX1 = axisY1 = vec3(0.0);
  gl_Position = pixelsToClip(corner == 0 ? p0 : p1);
#else
  vec3 x0, x1, y0, y1;
  neighbourAxis(cell, channel, ivec2(1, 0), start, end, dir, x0, x1);
  neighbourAxis(cell, channel, ivec2(0, 1), start, end, dir, y0, y1);
  axisX0 = mix(x0, x1, f0);
  axisY0 = mix(y0, y1, f0);
  axisX1 = mix(x0, x1, f1);
  axisY1 = mix(y0, y1, f1);
  // Reach on screen: 3 sigma of the widest axis plus the pixel footprint's blur, at each end.
  float pixelsPerRadian = 1.0 / u.volumePixel.x;
  float zA = max(-(va.z + (vb.z - va.z) * f0), kNearest);
  float zB = max(-(va.z + (vb.z - va.z) * f1), kNearest);
  float sigmaA = sqrt(dot(axisX0, axisX0) + dot(axisY0, axisY0));
  float sigmaB = sqrt(dot(axisX1, axisX1) + dot(axisY1, axisY1));
  float rA = 3.0 * sigmaA / zA * pixelsPerRadian + 2.0;
  float rB = 3.0 * sigmaB / zB * pixelsPerRadian + 2.0;
  vec2 n = vec2(-d.y, d.x);
  // Two triangles: (0, 1, 2), (2, 1, 3) over the corners below.
  const int order[6] = int[](0, 1, 2, 2, 1, 3);
  int k = order[corner];
  vec2 p = k < 2 ? p0 - d * rA + n * (k == 0 ? -rA : rA) : p1 + d * rB + n * (k == 2 ? -rB : rB);
  gl_Position = pixelsToClip(p);
#endif
}
