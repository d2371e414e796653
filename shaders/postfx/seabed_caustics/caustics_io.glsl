// Inputs and outputs shared by the caustics and floor passes, so the floor reads and writes
// exactly what the caustics pass does.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"

layout(binding = POSTFX_UNIT_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = POSTFX_UNIT_NORMAL) uniform sampler2D gbufferNormal;
layout(binding = POSTFX_UNIT_ALBEDO) uniform sampler2D gbufferAlbedo;
#include "postfx/seabed_caustics/water_texture.glsl"
#if POSTFX_SHADOW_MASK
layout(binding = POSTFX_UNIT_SHADOW) uniform sampler2DShadow sunShadowMap;
#endif

#ifndef POSTFX_LOOKUP_TARGET  // tile_irradiance_reduced.frag writes its own target
layout(location = 0) out vec4 outLight;  // blended ONE, ONE into the host's HDR target
#if POSTFX_RAW_OUTPUT
layout(location = 1) out float outRaw;   // not blended
#endif

// A pixel that gets no caustics: with the raw output it must still be written (0); without it,
// discard saves the blend.
void emitNothing() {
#if POSTFX_RAW_OUTPUT
  outLight = vec4(0.0);
  outRaw = 0.0;
#else
  discard;
#endif
}
#endif  // POSTFX_LOOKUP_TARGET

// log2 of the metres a pixel covers on the surface at camera-relative p (normal n, `distance`
// from the camera), widened where the surface is seen at a grazing angle, plus the water
// texture's lod bias: the mip level of a lookup of that footprint.
float surfaceLogFootprint(vec3 n, vec3 p, float distance) {
  float facing = max(abs(dot(n, p)) / max(distance, 1e-6), 0.25);
  return log2(max(distance * u.depthAndWater.w / facing, 1e-6)) + u.oblique.z;
}
