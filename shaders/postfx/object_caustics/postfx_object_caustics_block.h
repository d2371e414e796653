// Uniform block of the object-caustics passes (caster maps, splats, composite), one layout for
// C++ (filled in double on the CPU, then cast) and GLSL (std140). Only vec4/mat4 members, so
// std140 adds no padding and the C++ struct matches byte for byte (static_assert below).
// Positions are relative to the anchor: the snapped centre of the casters' sun footprint.
#ifndef POSTFX_SHARED_OBJECT_CAUSTICS_BLOCK_H
#define POSTFX_SHARED_OBJECT_CAUSTICS_BLOCK_H
#include "shared/common.h"

// Binding 0 is the seabed caustics block's: the passes never run together, and the state guard
// already saves and restores binding 0.
#define POSTFX_OBJECT_CAUSTICS_BLOCK_BINDING 0
#define POSTFX_MAX_CASTERS 64
#define POSTFX_CASTER_VEC4S 3

SHARED_BEGIN

#ifdef __cplusplus
struct ObjectCausticsBlock {
#else
layout(std140, binding = POSTFX_OBJECT_CAUSTICS_BLOCK_BINDING) uniform ObjectCausticsBlock {
#endif
  mat4 casterClip;           // anchor-relative world -> caster-map clip (orthographic, z in [0,1])
  mat4 receiverClip;         // anchor-relative world -> the host's receiver-map clip
  mat4 receiverClipInverse;  // receiver-map clip -> anchor-relative world
  mat4 viewToWorld;          // camera view -> world rotation (composite)
  // anchor-relative world -> caustic-map clip: orthographic along the sun, or the local light's
  // perspective view (a wider frustum than casterClip's, same axis).
  mat4 mapClip;
  // xyz: unit direction the light travels (a local light: the axis of its view); w: hit
  // iterations
  vec4 lightDir;
  vec4 lightRight;  // xyz: map u axis (unit); w: half side of the grid region (m; sun only)
  vec4 lightUp;     // xyz: map v axis (unit); w: half side of the map region (m; sun only)
  // xyz: the local light's position (anchor-relative, m); w: 1 for a local light, 0 the sun
  vec4 lightPosition;
  vec4 spotAxis;  // xyz: unit axis of a spot light; w: 1 spot, 0 point (or the sun)
  // x: outer half-angle of the spot cone (rad), y: inner one (full light), z: 1 when the local
  // light is under water (receivers above the water level get none of its light); w: unused
  vec4 spotCone;
  // rgb: water absorption per metre along a local light's path under water (light -> caster,
  // caster -> receiver); w: unused
  vec4 lightWater;
  vec4 grid;  // x: grid size, y: map size, z: splat sigma (map texels), w: flux per ray
  // x: caustic-map texels per metre, y: kMaxRoughSplatSigma (rough splats); zw: unused
  vec4 splatScale;
  vec4 receiver;      // x: 1 = [-1,1] depth convention, y: window depth of "no receiver" (far),
                      // z: receiver tolerance (m along the light),
                      // w: 1 when a caster is dispersed (one ray per channel)
  vec4 cameraOffset;  // xyz: camera - anchor (m); w: water level - anchor y (m)
  vec4 viewport;      // 1/width, 1/height, width, height
  vec4 viewOrigin;    // xy: the view's lower-left pixel in the target; zw: unused
  vec4 projection;    // P[0][0], P[1][1], P[2][0], P[2][1]
  vec4 depthParams;   // xy: P[2][2], P[3][2]; z: 1 when the casters are under water;
                      // w: back-surface (exit) iterations
  vec4 lightScale;    // rgb: sun irradiance (or light intensity) * intensity; w: unused
  // rgb: water absorption / cos(theta_t) per metre of depth, the sun's water column (0 for a
  // local light, absorbed along its path in the trace instead); w: unused
  vec4 waterAbsorption;
  vec4 viewExtinction;  // rgb: sigma_t along the view ray (1/m), 0 with ViewExtinction::Host
  // The volume caustics (Feature::VolumeCaustics), filled only when they draw this frame.
  // rgb: sigma_s * phase (GodRaySettings::intensity) * the light's scale (the sun's irradiance
  // or the light's intensity); w: a ray's grid cell: its area (m^2, the sun) or its solid angle
  // on the view's axis (sr, a local light)
  vec4 volumeLight;
  // rgb: sigma_t (1/m); w: 1 / cos of the refracted sun's angle from the vertical (0: a local
  // light)
  vec4 volumeExtinction;
  // x: god rays' surface fade (m), y: their depth fade (m, 0 none), z: maxDistance (m),
  // w: 1 when the volume caustics draw this frame (the trace writes the rays' segments)
  vec4 volumeFade;
  // x: radians per pixel at the view's centre (vertical); y: 1 = lines, 0 = beams; zw: unused
  vec4 volumePixel;
  // Per caster i (POSTFX_CASTER_VEC4S vec4s from i * POSTFX_CASTER_VEC4S):
  // [0] x: 0 refractive / 1 reflective, y: IOR relative to the outer medium (green),
  //     z: dispersion half spread of that relative IOR (0: one IOR), w: transmission;
  // [1] rgb: absorption per metre (refractive) or F0 (reflective), w: GGX alpha (roughness^2);
  // [2] rgb: tint of the transmitted light, w: 1 = thin-walled.
  vec4 materials[POSTFX_CASTER_VEC4S * POSTFX_MAX_CASTERS];
#ifdef __cplusplus
};
static_assert(sizeof(ObjectCausticsBlock) ==
                  5 * 64 + 22 * 16 + POSTFX_CASTER_VEC4S * POSTFX_MAX_CASTERS * 16,
              "ObjectCausticsBlock must match its std140 layout");
#else
}
u;
#endif

SHARED_END

#endif
