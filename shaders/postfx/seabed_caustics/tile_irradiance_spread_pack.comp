#version 450 core
// Tile irradiance, unresolved-slope spread, step 3 of 3: the blurred layers (copy 1 of the
// blur buffer, where tile_irradiance_spread_box.comp ends) four at a time into the RGBA16F texels of the
// irradiance array, relative to flat water and clamped, as tile_irradiance_resolve.comp does
// without the spread.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = POSTFX_STORAGE_TILE_BLUR) readonly buffer TileBlur {
  float blur[];  // ((copy * slots + slot) * layers + layer) * n^2 + z * n + x
};
layout(binding = POSTFX_IMAGE_TILE_IRRADIANCE, rgba16f) writeonly uniform image2DArray tileIrradiance;

// x: texels per side n, y: depth layers per slot; z: the clamp
layout(location = 0) uniform vec3 grid;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);  // z: array layer = slot * groups + group
  int n = int(grid.x), layers = int(grid.y);
  if (id.x >= n || id.y >= n) return;
  int groups = layers / 4;
  int slot = id.z / groups, group = id.z % groups;
  int slots = int(gl_NumWorkGroups.z) / groups;
  const int copy = 1;
  vec4 e;
  for (int j = 0; j < 4; ++j)
    e[j] = blur[uint((((copy * slots + slot) * layers + 4 * group + j) * n + id.y) * n + id.x)];
  imageStore(tileIrradiance, id, clamp(e, vec4(0.0), vec4(grid.z)));
}
