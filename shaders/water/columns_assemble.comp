#version 450 core
// Pass 2 of 2: transforms one x column of one cascade along z and writes the contract texels:
// slope = (dh/dx, dh/dz, h, J), displacement = (Dx, h, Dz, 0), to mip level 0.
// Defines: WATER_N, WATER_LOG2_N.
#include "shared/water_layout.h"
#include "water/fft_shared.glsl"

layout(local_size_x = WATER_N / 2) in;

layout(rgba32f, binding = WATER_SCRATCH_UNIT) uniform readonly image2DArray uScratch;
layout(rgba16f, binding = WATER_SLOPE_UNIT) uniform writeonly image2DArray uSlope;
layout(rgba16f, binding = WATER_DISPLACEMENT_UNIT) uniform writeonly image2DArray uDisplacement;

void main() {
  const uint column = gl_WorkGroupID.x;  // x index
  const uint cascade = gl_WorkGroupID.y;
  const uint tid = gl_LocalInvocationID.x;
  const int layer = int(cascade) * WATER_SCRATCH_LAYERS_PER_CASCADE;
  for (uint e = 0u; e < 2u; ++e) {
    const uint m = tid + e * uint(WATER_N / 2);
    const uint slot = bitReversed(m);
    lineA[slot] = imageLoad(uScratch, ivec3(column, m, layer));
    lineB[slot] = imageLoad(uScratch, ivec3(column, m, layer + 1));
  }
  inverseFftLine(tid);
  for (uint e = 0u; e < 2u; ++e) {
    const uint z = tid + e * uint(WATER_N / 2);
    const vec4 a = lineA[z];  // (h, dh/dx, dh/dz, Dx)
    const vec4 b = lineB[z];  // (Dz, dDx/dx, dDz/dz, dDx/dz)
    const ivec3 texel = ivec3(column, z, int(cascade));
    imageStore(uSlope, texel, vec4(a.y, a.z, a.x, waterJacobian(b.y, b.z, b.w)));
    imageStore(uDisplacement, texel, vec4(a.w, a.x, b.x, 0.0));
  }
}
