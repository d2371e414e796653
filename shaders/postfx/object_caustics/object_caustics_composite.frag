#version 450 core
// Adds the caustic map's light to every host pixel lying on a receiver ([2], III.B last
// step): the pixel is projected along the light (the sun's, or a local light's from its
// position) into the map; pixels not on the receiver depth map's surface (the casters themselves,
// anything between them and the light, anything in a receiver's shadow) get nothing.
#include "shared/common.h"
#include "postfx/common/postfx_bindings.h"
#include "shared/gbuffer_codec.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

#include "postfx/object_caustics/object_caustics_light.glsl"

layout(binding = POSTFX_UNIT_DEPTH) uniform sampler2D gbufferDepth;
layout(binding = POSTFX_UNIT_NORMAL) uniform sampler2D gbufferNormal;
layout(binding = POSTFX_UNIT_ALBEDO) uniform sampler2D gbufferAlbedo;
layout(binding = POSTFX_OBJECT_UNIT_CAUSTIC_MAP) uniform sampler2D causticMap;
layout(binding = POSTFX_OBJECT_UNIT_RECEIVER_DEPTH) uniform sampler2D receiverDepth;

layout(location = 0) out vec4 outLight;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float depth = texelFetch(gbufferDepth, pixel, 0).r;
  if (isSkyDepth(depth, POSTFX_DEPTH_CONVENTION)) discard;
  vec3 viewPos = viewPositionFromDepth((gl_FragCoord.xy - u.viewOrigin.xy) * u.viewport.xy, depth, u.projection,
                                       u.depthParams.xy, POSTFX_DEPTH_CONVENTION);
  vec3 p = mat3(u.viewToWorld) * viewPos + u.cameraOffset.xyz;  // anchor-relative
  vec3 n = decodeNormal(texelFetch(gbufferNormal, pixel, 0), POSTFX_NORMAL_ENCODING);
  vec3 l = lightRayAt(p);
  float nDotL = -dot(n, l);
  if (!(nDotL > 0.0)) discard;
  // A light under water does not light what lies above it (its rays would leave the water).
  if (u.spotCone.z > 0.5 && p.y > u.cameraOffset.w) discard;
  vec2 uv;
  if (!viewUv(u.mapClip, p, uv)) discard;
  if (!(all(greaterThanEqual(uv, vec2(0.0))) && all(lessThanEqual(uv, vec2(1.0))))) discard;

  vec4 clip = u.receiverClip * vec4(p, 1.0);
  if (!(clip.w > 0.0)) discard;
  vec3 ndc = clip.xyz / clip.w;
  vec2 ruv = ndc.xy * 0.5 + 0.5;
  if (!(all(greaterThanEqual(ruv, vec2(0.0))) && all(lessThanEqual(ruv, vec2(1.0))))) discard;
  // On the receiver: within `bias` metres of its surface along the light.
  float onReceiver = textureLod(receiverDepth, ruv, 0.0).r;
  float receiverNdc = u.receiver.x > 0.5 ? onReceiver * 2.0 - 1.0 : onReceiver;
  vec4 surface = u.receiverClipInverse * vec4(ndc.xy, receiverNdc, 1.0);
  if (!(surface.w != 0.0)) discard;
  if (!(abs(dot(surface.xyz / surface.w - p, l)) <= u.receiver.z)) discard;

  vec3 caustic = max(textureLod(causticMap, uv, 0.0).rgb, vec3(0.0));
  vec3 light = caustic * nDotL * u.lightScale.rgb;
  if (u.depthParams.z > 0.5) {  // under water: the water column between surface and receiver
    float depthBelow = max(u.cameraOffset.w - p.y, 0.0);
    light *= exp(-u.waterAbsorption.rgb * depthBelow);
  }
  // ViewExtinction::Plugin: from the receiver to the camera, the part of the ray under water.
  float receiverDepth = u.cameraOffset.w - p.y;
  if (receiverDepth > 0.0) {
    float submerged = submergedViewLength(length(p - u.cameraOffset.xyz), receiverDepth,
                                          u.cameraOffset.w - u.cameraOffset.y);
    light *= exp(-u.viewExtinction.rgb * submerged);
  }
  vec3 albedo = sanitizeAlbedo(texelFetch(gbufferAlbedo, pixel, 0).rgb);
  outLight = vec4(albedo * light, 0.0);
}
