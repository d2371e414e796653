#version 450 core
// One step of the damped 2D wave equation over the ripple heightfield (ripple_simulation.h):
// symplectic Euler, velocity first from the current heights, then heights from the new velocity.
// Stable for c dt sqrt(1/dx^2 + 1/dz^2) <= 1 (the host steps at half of it).
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rg32f) uniform readonly image2D current;  // height (m), velocity (m/s)
layout(binding = 1, rg32f) uniform writeonly image2D next;
uniform vec2 courantSquared;  // (c dt / dx)^2, (c dt / dz)^2
uniform float damping;        // 1/s, applied to the velocity
uniform vec2 spongeTexels;    // the absorbing band's width along u and v (texels; 0: none)
uniform float maxHeight;      // m: heights are clamped to +-maxHeight
uniform float stepSeconds;    // dt (s)
uniform vec2 viscosityWeights;  // nu dt / dx^2, nu dt / dz^2: the velocity's diffusion

vec2 stateAt(ivec2 p, ivec2 size) {
  // Reflecting walls: the neighbour beyond an edge is the edge texel itself, so no water flows
  // through it and the Laplacian sums to zero over the grid (the step keeps the volume).
  return imageLoad(current, clamp(p, ivec2(0), size - 1)).xy;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  ivec2 size = imageSize(current);
  if (any(greaterThanEqual(p, size))) return;
  vec2 state = imageLoad(current, p).xy;
  vec2 alongU = stateAt(p - ivec2(1, 0), size) + stateAt(p + ivec2(1, 0), size) - 2.0 * state;
  vec2 alongV = stateAt(p - ivec2(0, 1), size) + stateAt(p + ivec2(0, 1), size) - 2.0 * state;
  float h = state.x;
  // dt c^2 laplacian(h) = (courantSquared . second differences) / dt; the viscosity's
  // nu dt laplacian(v) damps a wave at nu k^2, the grid's shortest ones and not the ripples.
  float velocity = state.y + dot(courantSquared, vec2(alongU.x, alongV.x)) / stepSeconds +
                   dot(viscosityWeights, vec2(alongU.y, alongV.y));
  // The sponge: damping rises quadratically to 20/s at an absorbing edge.
  vec2 fromEdge = vec2(min(p, size - 1 - p)) + 0.5;
  vec2 depth = spongeTexels.x > 0.0 ? max(1.0 - fromEdge / spongeTexels, 0.0) : vec2(0.0);
  float band = max(depth.x, depth.y);
  velocity *= exp(-(damping + 20.0 * band * band) * stepSeconds);
  float height = h + stepSeconds * velocity;
  // The guards: a texel that is not finite returns to rest, and heights stay within the clamp.
  if (isnan(velocity) || isinf(velocity) || isnan(height) || isinf(height)) {
    velocity = 0.0;
    height = 0.0;
  }
  if (abs(height) > maxHeight) {
    height = clamp(height, -maxHeight, maxHeight);
    velocity = 0.0;  // the clamp is a wall the water stops at, not a spring
  }
  imageStore(next, p, vec4(height, velocity, 0.0, 0.0));
}
