// Shared by the two draws that splat the mirrored grid onto the view's receivers
// (ReflectedLanding::ViewDepth): the grid points reflected_receiver_rays.comp wrote, one grid
// triangle's light, and the view's projection (the caustics block's).
#include "postfx/common/postfx_bindings.h"

layout(binding = POSTFX_UNIT_GRID_POINTS) uniform samplerBuffer gridPoints;  // 2 texels per point
// x: flat water's flux through one grid triangle, sun.y * cell^2 / 2 (flat mirror light times
// m^2); y: ReflectedCausticsSettings::maxIrradiance; z: screen area (pixels^2) under which a
// triangle is deposited as a point instead of rasterised; w: grid points per side.
layout(location = 0) uniform vec4 splat;
// Camera-relative xz of the square (min xy, max zw) whose cells another grid lights (the outer
// grid's hole: the window); all 0 for none.
layout(location = 1) uniform vec4 hole;
// xyz: flat water's mirror ray reversed (receiver -> water), unit
layout(location = 3) uniform vec3 towardWater;
// xy: camera-relative xz of grid point (0, 0); z: the grid's spacing (m); w: 0 for the window's
// grid, 1 for the outer one (the light target's channels it writes)
layout(location = 2) uniform vec4 gridPlacement;

// One grid triangle's corners as they landed: camera-relative hit position and the light its
// ray carries (w; < 0: the ray met no receiver), and each hit's receiver normal.
struct GridTriangle {
  vec4 hit[3];
  vec3 normal[3];
  float spread[3];  // variance per axis of where its rays land about the hit (m^2)
};

GridTriangle gridTriangle(int triangle) {
  int points = int(splat.w);
  int cells = points - 1;
  int cell = triangle >> 1;
  ivec2 c = ivec2(cell % cells, cell / cells);
  // The cell's two triangles (00, 01, 10) and (01, 10, 11), as the refracted grid splits it.
  ivec2 corner[3];
  corner[0] = (triangle & 1) == 0 ? c : c + ivec2(0, 1);
  corner[1] = (triangle & 1) == 0 ? c + ivec2(0, 1) : c + ivec2(1, 0);
  corner[2] = (triangle & 1) == 0 ? c + ivec2(1, 0) : c + ivec2(1, 1);
  GridTriangle t;
  for (int k = 0; k < 3; ++k) {
    int i = 2 * (corner[k].y * points + corner[k].x);
    t.hit[k] = texelFetch(gridPoints, i);
    vec4 receiver = texelFetch(gridPoints, i + 1);
    t.normal[k] = receiver.xyz;
    t.spread[k] = receiver.w;
  }
  vec2 centre = gridPlacement.xy + (vec2(c) + 0.5) * gridPlacement.z;
  if (all(greaterThan(centre, hole.xy)) && all(lessThan(centre, hole.zw)))
    for (int k = 0; k < 3; ++k) t.hit[k].w = -1.0;  // lit by the finer grid
  return t;
}

// Whether the triangle landed whole on one surface, with the flux it carries (flat mirror light
// times m^2), the area it landed on (m^2) and its receiver's mean normal. Not where a corner's
// ray met no receiver, or the corners lie on different surfaces (normals apart, or a
// well-shaped triangle across planes: a pillar in front of a wall): its rays' light then lands
// at each ray's own hit (the point draw).
bool landedWhole(GridTriangle t, out float flux, out float area, out vec3 normal) {
  flux = splat.x * (max(t.hit[0].w, 0.0) + max(t.hit[1].w, 0.0) + max(t.hit[2].w, 0.0)) *
         (1.0 / 3.0);
  vec3 e1 = t.hit[1].xyz - t.hit[0].xyz, e2 = t.hit[2].xyz - t.hit[0].xyz;
  vec3 across = cross(e1, e2);
  area = 0.5 * length(across);
  normal = normalize(t.normal[0] + t.normal[1] + t.normal[2]);
  if (!(min(min(t.hit[0].w, t.hit[1].w), t.hit[2].w) >= 0.0)) return false;
  if (!(min(dot(t.normal[0], t.normal[1]),
            min(dot(t.normal[0], t.normal[2]), dot(t.normal[1], t.normal[2]))) > 0.8))
    return false;
  // A well-shaped triangle must lie in its receiver's plane; slivers (folds) say nothing.
  vec3 e3 = e2 - e1;
  float longest = max(max(dot(e1, e1), dot(e2, e2)), dot(e3, e3));
  if (2.0 * area > 0.2 * longest && abs(dot(across, normal)) < 0.8 * 2.0 * area) return false;
  return true;
}

// Whether a landed triangle goes to the point draw: under splat.z pixels^2 on screen and focused
// (brighter than twice flat water's light on its face). Rasterised, a seamless mesh lights each
// pixel centre from exactly one triangle, whatever their size; but a fold's tiny bright triangles
// would be hit or missed by the centres, their flux kept or lost by chance.
bool landsAsPoint(float pixels, float irradiance, vec3 normal) {
  float ratio = irradiance / max(dot(normal, towardWater), 0.05);
  return pixels < splat.z && !(ratio > 0.9 && ratio < 1.1);
}

// Clip position in the view of camera-relative point p (z inside both clip-control ranges).
vec4 viewClip(vec3 p) {
  vec3 v = transpose(mat3(u.viewToWorld)) * p;
  return vec4(u.projection.x * v.x + u.projection.z * v.z,
              u.projection.y * v.y + u.projection.w * v.z, 0.0, -v.z);
}

// View pixel coordinates of camera-relative point p.
vec2 viewPixels(vec3 p) {
  vec4 clip = viewClip(p);
  return (clip.xy / clip.w * 0.5 + 0.5) * u.viewport.zw;
}
