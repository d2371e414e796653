#version 450 core
#include "shared/gbuffer_codec.h"
in vec3 worldNormal;
uniform vec3 albedo;
layout(location = 0) out vec2 outNormal;  // RG16_SNORM octahedral
layout(location = 1) out vec4 outAlbedo;  // SRGB8_ALPHA8
void main() {
  vec3 n = safeNormalize(worldNormal);
  if (!gl_FrontFacing) n = -n;  // double-sided geometry: shade the side we see
  outNormal = octEncode(n);
  outAlbedo = vec4(albedo, 1.0);
}
