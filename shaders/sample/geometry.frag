#version 450 core
#include "shared/gbuffer_codec.h"
#include "sample/rock_detail.glsl"
in vec3 worldNormal;
in vec3 relativePosition;  // camera-relative world (m)
uniform vec3 albedo;
// 1 for the sample's rock and stone: procedural colour and bumps (rock_detail.glsl); 0 draws
// the material's flat colour, as a glTF model without textures asks.
uniform float surfaceDetail;
uniform vec3 cameraWorld;  // m: the noise is fixed to the world, not to the view
layout(location = 0) out vec2 outNormal;  // RG16_SNORM octahedral
layout(location = 1) out vec4 outAlbedo;  // SRGB8_ALPHA8
void main() {
  vec3 n = safeNormalize(worldNormal);
  if (!gl_FrontFacing) n = -n;  // double-sided geometry: shade the side we see
  vec3 colour = albedo;
  if (surfaceDetail > 0.5) {
    // The pixel's footprint in metres: octaves finer than two of it are left out (no shimmer).
    const float footprint = max(length(fwidth(relativePosition)), 1e-4);
    rockDetail(relativePosition + cameraWorld, footprint, n, colour);
  }
  outNormal = octEncode(n);
  outAlbedo = vec4(colour, 1.0);
}
