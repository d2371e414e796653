// Uniform block of the god-ray passes (binding 1; the caustics block at binding 0 supplies the
// camera, sun, water and shadow values both passes share). Only vec4 members: std140 adds no
// padding and the C++ struct matches byte for byte.
#ifndef POSTFX_SHARED_GODRAYS_BLOCK_H
#define POSTFX_SHARED_GODRAYS_BLOCK_H
#include "shared/common.h"

#define POSTFX_GODRAYS_BLOCK_BINDING 1

SHARED_BEGIN

#ifdef __cplusplus
struct GodRaysBlock {
#else
layout(std140, binding = POSTFX_GODRAYS_BLOCK_BINDING) uniform GodRaysBlock {
#endif
  vec4 gridX;            // xyz: grid x' axis in world (perpendicular to the plane of incidence);
                         // w: plane spacing s (m)
  vec4 gridZ;            // xyz: grid z' axis in world (the grid's up axis y' is the refracted sun);
                         // w: sample count
  vec4 gridOffset;       // x, y: camera's x', z' modulo s (m, in double on the CPU); z: 1 for
                         // uniform sampling along the ray; w: 1 for the screen-fixed dither
  vec4 fade;             // x: surface fade (m), y: depth fade (m), z: max distance (m), w: phase
                         // of the uniform sampling's samples within their steps (0.5)
  vec4 extinction;       // rgb: sigma_t = absorption + scattering (1/m); w: unused
  vec4 sunPath;          // rgb: sigma_t / cos(theta_t), per metre of depth (sun path); w: unused
  vec4 lightScale;       // rgb: sun irradiance * intensity; w: unused
  vec4 scattering;       // rgb: sigma_s (1/m); w: unused
  vec4 reducedViewport;  // 1/width, 1/height, width, height of the reduced-resolution texture
  vec4 reduction;        // x: pixels per reduced texel side k (1, 2, 4); yzw: unused
#ifdef __cplusplus
};
static_assert(sizeof(GodRaysBlock) == 10 * 16, "GodRaysBlock must match its std140 layout");
#else
}
g;
#endif

SHARED_END

#endif
