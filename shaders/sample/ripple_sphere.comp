#version 450 core
// A sphere moving through the ripple heightfield (webgl-water's moveSphere): each column's
// surface rises by the length of sphere below the level it gains, and falls by what it loses,
// so the water the sphere pushes aside is what the surface shows (physical sign and scale).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg32f) uniform image2D state;  // height (m), velocity (m/s)
uniform vec2 sizeMetres;  // the rectangle, m along u and v
uniform float maxHeight;  // m
uniform vec3 fromCentre;  // local u, height above the level, v (m)
uniform vec3 toCentre;
uniform float radius;  // m

// Length of the vertical chord through the sphere at `uv` that lies below the level (y = 0).
float submerged(vec2 uv, vec3 centre) {
  vec2 d = uv - centre.xz;
  float across = radius * radius - dot(d, d);
  if (across <= 0.0) return 0.0;
  float halfChord = sqrt(across);
  return max(min(centre.y + halfChord, 0.0) - (centre.y - halfChord), 0.0);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(state);
  if (any(greaterThanEqual(p, size))) return;
  vec2 local = ((vec2(p) + 0.5) / vec2(size) - 0.5) * sizeMetres;
  float change = submerged(local, toCentre) - submerged(local, fromCentre);
  if (change == 0.0) return;
  vec2 s = imageLoad(state, p).xy;
  s.x = clamp(s.x + change, -maxHeight, maxHeight);
  imageStore(state, p, vec4(s, 0.0, 0.0));
}
