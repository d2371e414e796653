#version 450 core
// The ripple heightfield's rectangle moved by whole texels (ripple_simulation.h, shift): each
// texel takes the state that lay under its world position before, and what enters from beyond
// the old rectangle is at rest.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg32f) uniform readonly image2D current;  // height (m), velocity (m/s)
layout(binding = 1, rg32f) uniform writeonly image2D next;
uniform ivec2 offset;  // texels the rectangle moved along u, v

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(current);
  if (any(greaterThanEqual(p, size))) return;
  ivec2 from = p + offset;
  bool inside = all(greaterThanEqual(from, ivec2(0))) && all(lessThan(from, size));
  imageStore(next, p, inside ? imageLoad(current, from) : vec4(0.0));
}
