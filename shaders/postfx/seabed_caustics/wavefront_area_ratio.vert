#version 450 core
// Wavefront area-ratio caustics [4], step 2 of 3: the refracted grid as one triangle
// strip per row (instance = row): vertex 2i + b of row j is grid point (i, j + b), placed where
// its ray meets the receiver. Its position in the incoming beam travels along for the fragment
// stage's area ratio.
#include "postfx/seabed_caustics/wavefront_area_ratio_common.glsl"

noperspective out vec2 beamTexels;  // incoming-beam position, in irradiance texels
noperspective out float transmit;   // Fresnel transmittance relative to flat water
#if defined(POSTFX_GRID_DRIFT)
// The ray's drift per metre of rise: affine over a triangle as its landing is, so the
// interpolated value is (to first order) the drift of the ray landing at the fragment.
noperspective out vec2 drift;
#endif

void main() {
  vec4 positions;
  gridPoint(ivec2(gl_VertexID >> 1, gl_InstanceID + (gl_VertexID & 1)), positions, transmit);
  beamTexels = positions.zw;
#if defined(POSTFX_GRID_DRIFT)
  drift = gridPointDrift(ivec2(gl_VertexID >> 1, gl_InstanceID + (gl_VertexID & 1)));
#endif
  gl_Position = receiverClip(positions.xy);
}
