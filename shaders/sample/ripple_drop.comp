#version 450 core
// A drop on the ripple heightfield: a raised-cosine bump added to the heights (webgl-water's
// drop), strength * (1 + cos(pi r / radius)) / 2 inside the radius.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg32f) uniform image2D state;  // height (m), velocity (m/s)
uniform vec2 sizeMetres;  // the rectangle, m along u and v
uniform float maxHeight;  // m
uniform vec2 centre;      // local u, v (m)
uniform float radius;     // m, at least a texel (host-clamped)
uniform float strength;   // m, within +-maxHeight (host-clamped)

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(state);
  if (any(greaterThanEqual(p, size))) return;
  vec2 local = ((vec2(p) + 0.5) / vec2(size) - 0.5) * sizeMetres;
  float r = length(local - centre) / radius;
  if (r >= 1.0) return;
  vec2 s = imageLoad(state, p).xy;
  s.x = clamp(s.x + strength * (0.5 + 0.5 * cos(3.14159265 * r)), -maxHeight, maxHeight);
  imageStore(state, p, vec4(s, 0.0, 0.0));
}
