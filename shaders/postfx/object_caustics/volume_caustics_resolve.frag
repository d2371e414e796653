#version 450 core
// Adds the volume caustics' light, summed in float at the view's size, to the view's rectangle
// of the host's target.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

layout(binding = POSTFX_OBJECT_UNIT_VOLUME_LIGHT) uniform sampler2D volumeLight;

layout(location = 0) out vec4 outLight;

void main() {
  vec3 light = texelFetch(volumeLight, ivec2(gl_FragCoord.xy - u.viewOrigin.xy), 0).rgb;
  if (!(light.r + light.g + light.b > 0.0)) discard;  // saves the blend
  outLight = vec4(light, 0.0);
}
