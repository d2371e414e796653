// Shared by the two draws of the irradiance pass: the grid points the compute step wrote
// (read as a buffer texture) and the count of the flux the clamp removes.
#include "postfx/common/postfx_bindings.h"

layout(binding = POSTFX_UNIT_GRID_POINTS) uniform samplerBuffer gridPoints;  // 2 texels per grid point
layout(location = 8) uniform float maxIrradiance;
// x: irradiance texels per side; y: area ratio above which a triangle is deposited as a point
// (its refracted area is under half a texel) instead of rasterised.
layout(location = 10) uniform vec2 raster;
layout(location = 9) uniform int pointsPerSide;

// Receiver xy and beam xy (texels), transmittance ratio, of grid point `index`.
void gridPoint(ivec2 index, out vec4 positions, out float transmit) {
  int i = 2 * (index.y * pointsPerSide + index.x);
  positions = texelFetch(gridPoints, i);
  transmit = texelFetch(gridPoints, i + 1).x;
}

#if defined(POSTFX_GRID_DRIFT)
// The ray's horizontal drift per metre of rise of grid point `index` (the reflected light's
// grid points carry it: reflected_light_vertices.comp).
vec2 gridPointDrift(ivec2 index) {
  return texelFetch(gridPoints, 2 * (index.y * pointsPerSide + index.x) + 1).yz;
}
#endif

vec4 receiverClip(vec2 texels) {
  // z = 0.5 lies inside both clip-control depth ranges.
  return vec4(texels * (2.0 / raster.x) - 1.0, 0.5, 1.0);
}
