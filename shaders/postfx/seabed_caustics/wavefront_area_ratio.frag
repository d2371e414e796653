#version 450 core
// Wavefront area-ratio caustics [4], triangles: irradiance = transmittance * beam area /
// receiver area. The ratio is the cross product of the beam position's screen derivatives
// (exact: the position is affine over the triangle, and helper invocations extrapolate the same
// plane), in beam texels per receiver texel, the signed area's magnitude so folded triangles
// count too. Blended ONE, ONE: overlapping folds sum.
// Triangles smaller than half a texel are left to the point draw: a texel centre would catch
// one with a probability of its area and then take its whole (huge) irradiance -- right on
// average, but noisy exactly at the caustic lines. The point deposits their flux instead.
#include "postfx/seabed_caustics/wavefront_area_ratio_common.glsl"
#include "postfx/seabed_caustics/wavefront_area_ratio_count.glsl"

noperspective in vec2 beamTexels;
noperspective in float transmit;

layout(location = 0) out float outIrradiance;
#if defined(POSTFX_GRID_DRIFT)
// The same light times its rays' drift (x, z), into the layers of the two drift channels.
noperspective in vec2 drift;
layout(location = 1) out float outDriftX;
layout(location = 2) out float outDriftZ;
#endif

void main() {
  vec2 dx = dFdx(beamTexels), dy = dFdy(beamTexels);
  float ratio = abs(dx.x * dy.y - dx.y * dy.x);
  if (!(ratio <= raster.y)) discard;  // a point carries it (NaN: no light)
  float e = transmit * ratio;
  float kept = min(e, maxIrradiance);
  countRemoved(e - kept);
  outIrradiance = kept;
#if defined(POSTFX_GRID_DRIFT)
  outDriftX = kept * drift.x;
  outDriftZ = kept * drift.y;
#endif
}
