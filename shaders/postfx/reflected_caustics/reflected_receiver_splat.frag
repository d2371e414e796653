#version 450 core
// Reflected caustics landing on the view's depth, steps 2 and 3 of 3: a landed grid triangle's
// light on the pixels of the receiver it landed on (the host's depth there within a few
// centimetres of its plane: the triangle does not light a pillar in front of its wall). With
// RECEIVER_POINTS, a sub-pixel triangle's flux over the four pixels around its landing by
// bilinear weights, over each pixel's area on the receiver.
#include "shared/common.h"
#include "shared/gbuffer_codec.h"
#include "postfx/common/postfx_bindings.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"

layout(binding = POSTFX_UNIT_DEPTH) uniform sampler2D gbufferDepth;

#if RECEIVER_POINTS
flat in vec3 position;
flat in float pointFlux;  // flat mirror light times m^2
flat in vec2 landing;     // view pixels
flat in float kernelRadius;  // > 0: a disc of that radius (m) on the receiver
#else
smooth in vec3 position;
flat in float irradiance;  // flat mirror light
#endif
flat in vec3 receiverNormal;
flat in float spreadVariance;  // per axis of where its rays land about it (m^2)

// The light, and the light times its landing variance (the lookup's blur reads their ratio):
// in rg for the window's grid, ba for the outer one (gridPlacement.w), blurred apart.
layout(location = 0) out vec4 outLight;
layout(location = 2) uniform vec4 gridPlacement;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel + ivec2(u.viewOrigin.xy), 0).r;
  if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) discard;
  vec3 v = viewPositionFromDepth(gl_FragCoord.xy * u.viewport.xy, depth, u.projection,
                                 u.depthAndWater.xy, POSTFX_DEPTH_CONVENTION);
  vec3 p = mat3(u.viewToWorld) * v;
  float distance = length(v);
  if (!(abs(dot(p - position, receiverNormal)) < 0.02 + 0.01 * distance)) discard;
#if RECEIVER_POINTS
  if (kernelRadius > 0.0) {
    float d2 = dot(p - position, p - position) / (kernelRadius * kernelRadius);
    if (!(d2 < 1.0)) discard;
    float light = pointFlux * (2.0 / 3.14159265) * (1.0 - d2) / (kernelRadius * kernelRadius);
    outLight = gridPlacement.w > 0.5 ? vec4(0.0, 0.0, light, light * spreadVariance)
                                     : vec4(light, light * spreadVariance, 0.0, 0.0);
    return;
  }
  vec2 d = abs(gl_FragCoord.xy - landing);
  vec2 w = mix(0.5 * (1.5 - d) * (1.5 - d), 0.75 - d * d, lessThan(d, vec2(0.5)));
  w = mix(w, vec2(0.0), greaterThanEqual(d, vec2(1.5)));
  // The pixel's area on the receiver: its solid angle times distance^2 over the cosine there.
  float axisCosine = -v.z / max(distance, 1e-6);
  float facing = max(abs(dot(receiverNormal, p)) / max(distance, 1e-6), 0.05);
  float area = 4.0 * v.z * v.z * u.viewport.x * u.viewport.y / (u.projection.x * u.projection.y) *
               axisCosine / facing;
  float light = pointFlux * w.x * w.y / max(area, 1e-12);
#else
  float light = irradiance;
#endif
  outLight = gridPlacement.w > 0.5 ? vec4(0.0, 0.0, light, light * spreadVariance)
                                   : vec4(light, light * spreadVariance, 0.0, 0.0);
}
