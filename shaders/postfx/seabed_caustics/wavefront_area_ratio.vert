#version 450 core
// Wavefront area-ratio caustics [4], step 2 of 3: the refracted grid as one triangle
// strip per row (instance = row): vertex 2i + b of row j is grid point (i, j + b), placed where
// its ray meets the receiver. Its position in the incoming beam travels along for the fragment
// stage's area ratio.
#include "postfx/seabed_caustics/wavefront_area_ratio_common.glsl"

noperspective out vec2 beamTexels;  // incoming-beam position, in irradiance texels
noperspective out float transmit;   // Fresnel transmittance relative to flat water

void main() {
  vec4 positions;
  gridPoint(ivec2(gl_VertexID >> 1, gl_InstanceID + (gl_VertexID & 1)), positions, transmit);
  beamTexels = positions.zw;
  gl_Position = receiverClip(positions.xy);
}
