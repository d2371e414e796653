#version 450 core
// One Gaussian point per traced ray (image-space photon gathering), its flux added into the
// caustic map where the trace pass found the ray lands, its shape taken from where the rays of
// the neighbouring cells land.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

// The trace pass's results: see object_caustics_trace.comp.
layout(binding = POSTFX_OBJECT_UNIT_LANDINGS) uniform sampler2DArray landings;

flat out vec2 splatCentre;  // map texels
flat out vec3 splatFlux;
flat out vec3 splatShape;  // covariance, texels^2 (splatCovariance)

void dropRay() {
  gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: culled
  gl_PointSize = 1.0;
  splatCentre = vec2(0.0);
  splatFlux = vec3(0.0);
  splatShape = vec3(1.0, 0.0, 1.0);
}

// Where the ray of a cell lands (map texels); false when it does not (or lies off the grid).
bool landing(ivec2 cell, int channel, out vec2 centre) {
  centre = vec2(0.0);
  if (any(lessThan(cell, ivec2(0))) || any(greaterThanEqual(cell, ivec2(int(u.grid.x))))) {
    return false;
  }
  vec4 record = texelFetch(landings, ivec3(cell, 2 * channel), 0);
  centre = record.xy;
  return record.w > 0.5;
}

// The vector (map texels) from centre to where the ray of a neighbouring cell along axis lands:
// the nearer of the cells before and after, so that a neighbour across a discontinuity (the
// silhouette, the edge of total internal reflection) does not widen the splat; 0 when neither
// lands.
vec2 neighbourSpacing(ivec2 cell, int channel, ivec2 axis, vec2 centre) {
  vec2 after, before;
  bool hasAfter = landing(cell + axis, channel, after);
  bool hasBefore = landing(cell - axis, channel, before);
  vec2 a = after - centre, b = centre - before;
  if (hasAfter && hasBefore) return dot(a, a) < dot(b, b) ? a : b;
  return hasAfter ? a : (hasBefore ? b : vec2(0.0));
}

void main() {
  int size = int(u.grid.x);
  ivec2 cell = ivec2(gl_VertexID % size, gl_VertexID / size);
  int channel = gl_InstanceID;
  vec4 record = texelFetch(landings, ivec3(cell, 2 * channel), 0);
  if (!(record.w > 0.5)) {
    dropRay();
    return;
  }
  splatCentre = record.xy;
  splatFlux = texelFetch(landings, ivec3(cell, 2 * channel + 1), 0).rgb;
  vec2 alongX = neighbourSpacing(cell, channel, ivec2(1, 0), splatCentre);
  vec2 alongY = neighbourSpacing(cell, channel, ivec2(0, 1), splatCentre);
  // A ray whose beam spreads over several times its own cross-section lands in a dim, divergent
  // part (a lens's outer halo) where the casters' maps, not the optics, decide its neighbours:
  // their texels and facets bunch those rays into spokes. Round splats there (the halo is
  // smooth in the traced reference); keep them elongated where light converges, so that a point
  // or line caustic stays sharp.
  float spreadArea = abs(alongX.x * alongY.y - alongX.y * alongY.x) / u.grid.w;
  splatShape =
      splatCovariance(record.z, alongX, alongY, u.splatScale.y, smoothstep(1.5, 4.0, spreadArea));
  // The trace stored only finite landings and flux; a neighbour's landing can still make the
  // shape NaN or Inf, which fails these comparisons and never reaches the map.
  if (!(all(greaterThanEqual(splatShape.xz, vec2(u.grid.z * u.grid.z))) &&
        all(lessThan(splatShape, vec3(1e30))))) {
    dropRay();
    return;
  }
  gl_PointSize = splatSpriteSize(sqrt(max(splatShape.x, splatShape.z)));
  vec2 uv = splatCentre / u.grid.y;
  gl_Position = vec4(uv * 2.0 - 1.0, 0.5, 1.0);
}
