#version 450 core
// Traces every ray of the caster grid once (one invocation per cell and colour channel) and
// stores where it lands, so that the splat pass can shape each ray's Gaussian from where its
// neighbours land without tracing them again.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

#include "postfx/object_caustics/object_caustics_trace.glsl"

// 8 x 8 cells a group, the grid's cells along x and y and the colour channel along z: a 1D
// dispatch of 64 cells a group would need 65,536 groups at the 2048 grid, one past the
// GL_MAX_COMPUTE_WORK_GROUP_COUNT GL guarantees (65,535).
layout(local_size_x = 8, local_size_y = 8) in;

// Layer 2c: (centre in map texels, splat sigma, 1 where the ray lands, else 0); layer 2c + 1:
// its flux. c: the colour channel (0 only without dispersion).
layout(binding = POSTFX_IMAGE_OBJECT_LANDINGS, rgba32f) uniform writeonly image2DArray landings;

void main() {
  int size = int(u.grid.x);
  ivec2 cell = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(cell, ivec2(size)))) return;
  int channel = int(gl_GlobalInvocationID.z);
  vec2 centre;
  vec3 flux;
  float sigma;
  RaySegment segment;
  bool lands = traceCell(cell, channel, centre, flux, sigma, segment);
  // NaN fails every comparison, Inf fails the bound: neither reaches the map.
  lands = lands && all(lessThan(abs(flux), vec3(1e30))) && all(lessThan(abs(centre), vec2(1e30))) &&
          sigma >= u.grid.z && sigma < 1e30;
  imageStore(landings, ivec3(cell, 2 * channel), lands ? vec4(centre, sigma, 1.0) : vec4(0.0));
  imageStore(landings, ivec3(cell, 2 * channel + 1), vec4(lands ? flux : vec3(0.0), 0.0));
#if POSTFX_VOLUME_CAUSTICS
  if (u.volumeFade.w > 0.5) {
    // After every channel's two landing layers: this channel's start, end and power.
    int base = (u.receiver.w > 0.5 ? 6 : 2) + 3 * channel;
    bool drawn = lands && all(lessThan(abs(segment.start), vec3(1e30))) &&
                 all(lessThan(abs(segment.end), vec3(1e30))) &&
                 all(lessThan(abs(segment.power), vec3(1e30))) &&
                 all(greaterThanEqual(segment.power, vec3(0.0)));
    imageStore(landings, ivec3(cell, base), drawn ? vec4(segment.start, 1.0) : vec4(0.0));
    imageStore(landings, ivec3(cell, base + 1), vec4(drawn ? segment.end : vec3(0.0), 0.0));
    imageStore(landings, ivec3(cell, base + 2), vec4(drawn ? segment.power : vec3(0.0), 0.0));
  }
#endif
}
