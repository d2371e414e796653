// What the god-ray march and its upsample share: the inputs (caustics_io.glsl, both uniform
// blocks) and each pixel's view ray and distance from the G-buffer depth.
#include "postfx/seabed_caustics/caustics_io.glsl"
#include "shared/gbuffer_codec.h"
#include "postfx/god_rays/postfx_godrays_block.h"

// Distance stored for sky pixels (and the clamp of any other): below RGBA16F's max (65504),
// far past any march (maxDistance <= 1e5 is clipped by the scene anyway).
const float kSkyDistance = 65000.0;

// View-space unit direction of `pixel` and the distance to what it sees (kSkyDistance for the
// sky). A NaN depth texel gives a NaN distance, which the callers treat as "nothing here".
vec3 pixelViewRay(ivec2 pixel, out float pixelDistance) {
  vec2 uv = (vec2(pixel) - u.viewOrigin.xy + 0.5) * u.viewport.xy;  // pixel: in the target
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) {
    vec2 ndc = uv * 2.0 - 1.0;
    vec3 dir = vec3((ndc.x + u.projection.z) / u.projection.x,
                    (ndc.y + u.projection.w) / u.projection.y, -1.0);
    pixelDistance = kSkyDistance;
    return normalize(dir);
  }
  vec3 viewPos = viewPositionFromDepth(uv, depth, u.projection, u.depthAndWater.xy,
                                       POSTFX_DEPTH_CONVENTION);
  float len = length(viewPos);
  pixelDistance = min(len, kSkyDistance);
  return viewPos / max(len, 1e-20);
}
