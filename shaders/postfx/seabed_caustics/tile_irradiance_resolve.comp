#version 450 core
// Tile irradiance, step 2 of 2: the accumulated flux of four depth layers becomes one RGBA16F
// texel of the irradiance array (relative to flat water, clamped), and the accumulators are
// zeroed for the next cascade and frame (cheaper than a separate clear).
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = POSTFX_STORAGE_TILE_ACCUMULATORS) buffer TileAccumulators {
  uint accumulators[];
};
layout(binding = POSTFX_IMAGE_TILE_IRRADIANCE, rgba16f) writeonly uniform image2DArray tileIrradiance;

// x: texels per side, y: first accumulator layer, z: first array layer, w: clamp
layout(location = 0) uniform vec4 resolve;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  int side = int(resolve.x);
  if (id.x >= side || id.y >= side) return;
  vec4 irradiance;
  for (int j = 0; j < 4; ++j) {
    int layer = int(resolve.y) + 4 * id.z + j;
    uint index = uint((layer * side + id.y) * side + id.x);
    irradiance[j] = min(float(accumulators[index]) * (1.0 / TILE_FIXED_POINT), resolve.w);
    accumulators[index] = 0u;
  }
  imageStore(tileIrradiance, ivec3(id.xy, int(resolve.z) + id.z), irradiance);
}
