#version 450 core
// Depth-aware (joint bilateral) upsample of the reduced-resolution god rays, added into the host
// target. Each full-resolution pixel blends the four reduced texels around it by bilinear
// weight times the similarity of their distances (stored in alpha by the march), so shafts do
// not bleed across silhouettes; when no neighbour matches, the closest in distance is taken.
#include "postfx/god_rays/godrays_common.glsl"
#include "postfx/god_rays/postfx_godrays.h"

// Each texel: (packHalf2x16(r, g), packHalf2x16(b, distance)), godrays.frag's reduced march.
layout(binding = POSTFX_UNIT_GODRAYS_REDUCED) uniform usampler2D reducedGodRays;

// Relative distance difference at which a neighbour's weight falls to 1/4.
const float kDepthTolerance = 0.05;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float z0;
  vec3 d = mat3(u.viewToWorld) * pixelViewRay(pixel, z0);
  if (!(z0 > 0.0)) discard;  // NaN depth texel
  // A pixel whose own view ray has no underwater part gets no light, whatever its reduced
  // neighbours hold: a wall 9 mm above the water, seen from above it, once took a shaft's
  // half-float step from the texel below the waterline at the same distance.
  vec2 range = godRayUnderwaterRange(u.depthAndWater.z, d.y, min(z0, g.fade.z));
  if (!(range.y > range.x)) discard;
  // Reduced texel i sits on full pixel k*i; pixel k*i + j lies j/k of the way to texel i + 1.
  int k = int(g.reduction.x);
  ivec2 local = pixel - ivec2(u.viewOrigin.xy);  // in the view
  ivec2 base = local / k;
  vec2 f = vec2(local - base * k) / float(k);
  // Two gathers at the corner between texels base and base + 1 read both words of all four,
  // clamped to the edge (the texture is exactly the reduced viewport's size).
  vec2 corner = vec2(base + 1) * g.reducedViewport.xy;
  uvec4 redGreen = textureGather(reducedGodRays, corner, 0);
  uvec4 blueDistance = textureGather(reducedGodRays, corner, 1);
  // Gather order: texels (0,1), (1,1), (1,0), (0,0) from base.
  vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  vec3 sum = vec3(0.0), best = vec3(0.0);
  float weightSum = 0.0, bestDiff = 3.0e38;
  for (int i = 0; i < 4; ++i) {
    vec2 bd = unpackHalf2x16(blueDistance[i]);
    vec3 tap = vec3(unpackHalf2x16(redGreen[i]), bd.x);
    float diff = abs(bd.y - z0) / z0;
    if (diff < bestDiff) {
      bestDiff = diff;
      best = tap;
    }
    // Squared Cauchy falloff rather than exp: as steep past the tolerance (1/676 at 5x, exp
    // gives 1/148), no transcendental.
    float x = diff * (1.0 / kDepthTolerance);
    float q = 1.0 + x * x;
    float w = bilinear[i] / (q * q);
    sum += w * tap;
    weightSum += w;
  }
  // The march stored light per unit of the sun's (godrays.frag).
  vec3 light = g.lightScale.rgb * (weightSum > 1e-4 ? sum / weightSum : best);
  if (!(light.r + light.g + light.b > 0.0) || !all(lessThan(light, vec3(1e30)))) discard;
  outLight = vec4(light, 0.0);
}
