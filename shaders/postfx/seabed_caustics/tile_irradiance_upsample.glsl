// The TileIrradiance lookups at reduced resolution (tile_irradiance_reduced.frag), read back per
// full-resolution pixel. Include after caustics_io.glsl.

// Distance stored for texels with no surface (sky, broken depth): below RGBA16F's max (65504),
// and far from any surface's, so a pixel's depth similarity never picks it.
const float kReducedNoSurface = 65000.0;

#ifndef POSTFX_TILE_REDUCED
#define POSTFX_TILE_REDUCED 0
#endif
#if POSTFX_TILE_REDUCED
// Each texel: packHalf2x16(irradiance, distance) (tile_irradiance_reduced.frag).
layout(binding = POSTFX_UNIT_TILE_REDUCED) uniform usampler2D reducedTileIrradiance;

// Relative distance difference at which a texel's weight falls to 1/4 (as the god rays'
// upsample): the irradiance of a surface behind a silhouette does not bleed onto the one before it.
const float kReducedDepthTolerance = 0.05;

// Irradiance at full-resolution `pixel` at `distance` from the camera: the four reduced texels
// around it (texel i sits on pixel 2i) by bilinear weight times distance similarity; when none
// matches, the closest in distance. An even pixel reads its own texel exactly. One gather reads
// all four (a CPU rasteriser pays per fetch); clamped to the edge as the target is.
float upsampledTileIrradiance(ivec2 pixel, float distance) {
  ivec2 base = pixel >> 1;
  vec2 f = vec2(pixel & 1) * 0.5;
  vec2 corner = vec2(base + 1) / vec2(textureSize(reducedTileIrradiance, 0));
  // Gather order: (0,1), (1,1), (1,0), (0,0) texels from base.
  uvec4 texels = textureGather(reducedTileIrradiance, corner, 0);
  vec4 bilinear = vec4((1.0 - f.x) * f.y, f.x * f.y, f.x * (1.0 - f.y), (1.0 - f.x) * (1.0 - f.y));
  float sum = 0.0, weightSum = 0.0, best = 1.0, bestDiff = 3.0e38;
  for (int k = 0; k < 4; ++k) {
    vec2 tap = unpackHalf2x16(texels[k]);
    float diff = abs(tap.y - distance) / max(distance, 1e-6);
    if (diff < bestDiff) {
      bestDiff = diff;
      best = tap.x;
    }
    float x = diff * (1.0 / kReducedDepthTolerance);
    float q = 1.0 + x * x;
    float w = bilinear[k] / (q * q);
    sum += w * tap.x;
    weightSum += w;
  }
  return weightSum > 1e-4 ? sum / weightSum : best;
}
#endif
