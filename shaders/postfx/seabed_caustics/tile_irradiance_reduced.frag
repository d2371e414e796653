#version 450 core
// The TileIrradiance model's lookups at reduced resolution (CausticsLookupResolution::Half):
// texel i looks the irradiance up for full-resolution pixel 2i and keeps that pixel's distance,
// so that caustics.frag (POSTFX_TILE_REDUCED) can blend the four texels around each pixel by
// depth similarity. The lookups are the model's cost on a CPU rasteriser (four filtered fetches,
// the second cascade's coordinate depending on the first's); the light they give varies on the
// scale of the caustic network, several pixels wide, which a bilinear upsample keeps.
// Compile-time switches: those of caustics.frag's TileIrradiance variant.
#define POSTFX_LOOKUP_TARGET 1
#include "postfx/seabed_caustics/caustics_io.glsl"
#include "shared/gbuffer_codec.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/water_sampling.glsl"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"
#include "postfx/seabed_caustics/tile_irradiance_lookup.glsl"
#include "postfx/seabed_caustics/tile_irradiance_upsample.glsl"

// Irradiance and distance as two halves of one texel: the upsample gathers a pixel's four
// texels, both values, with one fetch.
layout(location = 0) out uint outLookup;

void main() {
  // Texel i stands for the view's pixel 2i; the G-buffer is read where the view lies in it.
  ivec2 local = min(ivec2(gl_FragCoord.xy) * 2, ivec2(u.viewport.zw) - 1);
  ivec2 pixel = local + ivec2(u.viewOrigin.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  float e = 1.0, distance = kReducedNoSurface;
  if (!isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) {
    vec3 viewPos = viewPositionFromDepth((vec2(local) + 0.5) * u.viewport.xy, depth, u.projection,
                                         u.depthAndWater.xy, POSTFX_DEPTH_CONVENTION);
    vec3 p = mat3(u.viewToWorld) * viewPos;
    float depthBelow = u.depthAndWater.z - p.y;
    float len = length(viewPos);
    if (len < kReducedNoSurface) distance = len;  // NaN (a broken depth texel) stays "none"
    if (depthBelow > 0.0 && distance < kReducedNoSurface) {
      vec3 n = decodeNormal(texelFetch(gbufferNormal, pixel, 0), POSTFX_NORMAL_ENCODING);
      // The texel stands for 2 x 2 pixels: filtered over that footprint, so the reduced image
      // does not alias what the upsample then interpolates.
      e = tileIrradianceAt(p, depthBelow, surfaceLogFootprint(n, p, distance) + 1.0);
    }
  }
  outLookup = packHalf2x16(vec2(e, distance));
}
