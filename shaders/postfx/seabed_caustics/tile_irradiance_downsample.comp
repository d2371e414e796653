#version 450 core
// Tile irradiance, the mip chain: each texel of a level is the mean of the 2 x 2 texels of the
// level above (the box filter of glGenerateTextureMipmap), every array layer in one dispatch.
// A CPU driver generates mips level by level and layer by layer through its blitter, which cost
// a third of the field's pre-pass on llvmpipe.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = POSTFX_UNIT_TILE_IRRADIANCE) uniform sampler2DArray finer;
layout(binding = POSTFX_IMAGE_TILE_IRRADIANCE, rgba16f) writeonly uniform image2DArray coarser;

// x: texels per side of the level written, y: the level read (the one above it)
layout(location = 0) uniform ivec2 level;

void main() {
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (id.x >= level.x || id.y >= level.x) return;
  ivec3 at = ivec3(id.xy * 2, id.z);
  vec4 sum = texelFetch(finer, at, level.y) + texelFetch(finer, at + ivec3(1, 0, 0), level.y) +
             texelFetch(finer, at + ivec3(0, 1, 0), level.y) +
             texelFetch(finer, at + ivec3(1, 1, 0), level.y);
  imageStore(coarser, id, 0.25 * sum);
}
