#version 450 core
// Wavefront area-ratio caustics [4], step 3 of 3: one point per grid triangle (vertex
// 2 c + t is triangle t of cell c, the strip's split), kept only for triangles whose refracted
// area is under half a texel (area ratio above raster.y, the triangle draw's exact
// complement). It deposits the triangle's whole flux around its landing, split over the four
// texels nearest to it by bilinear weights (a 2-texel point): flux-exact, and as the water
// moves the flux slides between texels instead of jumping from one to the next (which flickered
// where folds are drawn as points).
#include "postfx/seabed_caustics/wavefront_area_ratio_common.glsl"

flat out float keptFlux;     // texel-areas of flat-water flux this point adds
flat out float removedFlux;  // what the clamp took from it
flat out vec2 landing;      // where it lands, in texels (window coordinates)
#if defined(POSTFX_GRID_DRIFT)
flat out vec2 keptDrift;  // keptFlux times its rays' mean drift per metre of rise
#endif

float cross2(vec2 a, vec2 b) {
  return a.x * b.y - a.y * b.x;
}

void main() {
  int cells = pointsPerSide - 1;
  int cell = gl_VertexID >> 1;
  ivec2 c = ivec2(cell % cells, cell / cells);
  // The strip's triangles of cell c: (00, 01, 10) and (01, 10, 11).
  ivec2 a = (gl_VertexID & 1) == 0 ? c : c + ivec2(0, 1);
  ivec2 b = (gl_VertexID & 1) == 0 ? c + ivec2(0, 1) : c + ivec2(1, 0);
  ivec2 d = (gl_VertexID & 1) == 0 ? c + ivec2(1, 0) : c + ivec2(1, 1);
  vec4 p0, p1, p2;
  float t0, t1, t2;
  gridPoint(a, p0, t0);
  gridPoint(b, p1, t1);
  gridPoint(d, p2, t2);
  float beamArea = 0.5 * abs(cross2(p1.zw - p0.zw, p2.zw - p0.zw));
  float receiverArea = 0.5 * abs(cross2(p1.xy - p0.xy, p2.xy - p0.xy));
  float flux = (t0 + t1 + t2) * (1.0 / 3.0) * beamArea;
  keptFlux = 0.0;
  removedFlux = 0.0;
  landing = vec2(0.0);
#if defined(POSTFX_GRID_DRIFT)
  keptDrift = vec2(0.0);
#endif
  // Rasterised by the triangle draw (ratio <= raster.y, written as its complement so the
  // rounding of both sides agrees as far as it can): this point is culled.
  if (!(beamArea > raster.y * receiverArea) || !(flux > 0.0) || !(flux < 3.0e38)) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume
    gl_PointSize = 1.0;
    return;
  }
  keptFlux = min(flux, maxIrradiance * receiverArea);
  removedFlux = flux - keptFlux;
  landing = (p0.xy + p1.xy + p2.xy) * (1.0 / 3.0);
#if defined(POSTFX_GRID_DRIFT)
  keptDrift = keptFlux * (gridPointDrift(a) + gridPointDrift(b) + gridPointDrift(d)) * (1.0 / 3.0);
#endif
  gl_Position = receiverClip(landing);
  // Covers exactly the texel centres within one texel of the landing on both axes: the four
  // bilinear neighbours (the others the fragment stage weighs 0).
  gl_PointSize = 2.0;
}
