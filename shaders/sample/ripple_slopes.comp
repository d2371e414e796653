#version 450 core
// The ripple heightfield's output texture (postfx::LocalWater's layout): RG = slopes dh/du,
// dh/dv by central differences (an edge texel's outer neighbour is itself, as in the step),
// B = height (m), A = velocity (m/s).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg32f) uniform readonly image2D state;  // height (m), velocity (m/s)
layout(binding = 1, rgba32f) uniform writeonly image2D water;
uniform vec2 texelMetres;  // m per texel along u and v

float heightAt(ivec2 p, ivec2 size) {
  return imageLoad(state, clamp(p, ivec2(0), size - 1)).x;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(state);
  if (any(greaterThanEqual(p, size))) return;
  vec2 s = imageLoad(state, p).xy;
  float du = heightAt(p + ivec2(1, 0), size) - heightAt(p - ivec2(1, 0), size);
  float dv = heightAt(p + ivec2(0, 1), size) - heightAt(p - ivec2(0, 1), size);
  imageStore(water, p, vec4(du / (2.0 * texelMetres.x), dv / (2.0 * texelMetres.y), s.x, s.y));
}
