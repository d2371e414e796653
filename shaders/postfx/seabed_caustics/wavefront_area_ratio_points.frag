#version 450 core
// Wavefront area-ratio caustics [4], points: a sub-texel triangle's flux over the four
// texels around its landing, by bilinear weights that sum to 1 (irradiance = flux / texel area,
// the texel being the unit of area).
#include "postfx/seabed_caustics/wavefront_area_ratio_count.glsl"

flat in float keptFlux;
flat in float removedFlux;
flat in vec2 landing;

layout(location = 0) out float outIrradiance;
#if defined(POSTFX_GRID_DRIFT)
flat in vec2 keptDrift;
layout(location = 1) out float outDriftX;
layout(location = 2) out float outDriftZ;
#endif

void main() {
  vec2 w = max(1.0 - abs(gl_FragCoord.xy - landing), 0.0);
  float share = w.x * w.y;
  countRemoved(removedFlux * share);
  outIrradiance = keptFlux * share;
#if defined(POSTFX_GRID_DRIFT)
  outDriftX = keptDrift.x * share;
  outDriftZ = keptDrift.y * share;
#endif
}
