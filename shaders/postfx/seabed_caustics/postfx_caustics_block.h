// Uniform block of the caustics and floor passes, one layout for C++ (filled in double on the
// CPU, then cast) and GLSL (std140). Only vec4/mat4 members, so std140 adds no padding and the
// C++ struct matches byte for byte (static_assert below).
#ifndef POSTFX_SHARED_CAUSTICS_BLOCK_H
#define POSTFX_SHARED_CAUSTICS_BLOCK_H
#include "shared/common.h"

#define POSTFX_CAUSTICS_BLOCK_BINDING 0
#define POSTFX_MAX_CASCADES 4

SHARED_BEGIN

#ifdef __cplusplus
struct CausticsBlock {
#else
layout(std140, binding = POSTFX_CAUSTICS_BLOCK_BINDING) uniform CausticsBlock {
#endif
  mat4 viewToWorld;         // rotation only: view space -> camera-relative world space
  mat4 shadowMatrix;        // camera-relative world -> light clip space
  vec4 viewport;            // 1/width, 1/height, width, height
  vec4 projection;          // P[0][0], P[1][1], P[2][0], P[2][1]
  vec4 depthAndWater;       // P[2][2], P[3][2], water level - camera y (m), radians per pixel
  vec4 towardSun;           // xyz: unit vector toward the sun; w: tau
  vec4 reference;           // xyz: unit vector perpendicular to the plane of incidence (the god
                            // rays' factor); w: reflection weight
  vec4 refractedUp;         // xyz: unperturbed refracted sun ray reversed (receiver -> surface)
                            // w: surface fade depth (m)
  vec4 eta;                 // 1 / IOR for R, G, B; w: tri-planar sharpness
  vec4 lightScale;          // sun irradiance * intensity (rgb); w: min cascade contrast
  vec4 absorptionPerDepth;  // absorption / cos(theta_t), per metre of depth (rgb); w: unused
  vec4 viewExtinction;      // rgb: sigma_t along the view ray (1/m), 0 with ViewExtinction::Host
  vec4 oblique;             // refractedUp.xz / refractedUp.y (x, y); z: lod bias; w: cascades
  vec4 cascadeAxes[POSTFX_MAX_CASCADES];     // fract((camera - water origin) / tile) along x, y,
                                             // z; w: 1 / tile (1/m)
  vec4 cascadeOblique[POSTFX_MAX_CASCADES];  // fract of the camera's oblique coordinates u, v;
                                             // z: log2(texels per metre); w: unused
  vec4 cascadeSkip[POSTFX_MAX_CASCADES];     // x: irradiance modulation per metre below the level
                                             // (< 0: unknown, always sampled); y: log2 of half the
                                             // longest wavelength (m; huge: unknown); z: unused;
                                             // w: see tileIrradiance
  vec4 shadowParams;         // x: bias toward the light (m), y: 1 for a [-1,1] shadow convention,
                             // z: unused, w: floor-pass scale (always 0)
  vec4 shadowLight;          // w 0: xyz unit vector toward the light (orthographic map); w 1:
                             // xyz the light's camera-relative position (perspective map)
  vec4 shadowNormalOffset;   // xy: normal offset (m) per clip w per texel-fraction of the map along
                             // x and y (normalOffsetTexels * 2 / |matrix row|); zw: unused
  vec4 irradianceWindow;     // WavefrontAreaRatio: xy: camera-relative world xz of the window's
                             // corner (m); z: 1 / window size (1/m); w: layer count (0: the
                             // model is off)
  vec4 irradianceDepths[2];  // depth below the level of layers 0-3 and 4-7 (m)
  vec4 tileIrradiance;       // TileIrradiance: x: depth layers (0 = model off), y: 1 / deepest
                             // layer's depth (1/m); zw: unused. Per cascade, cascadeSkip w:
                             // log2(irradiance texels per metre). Which cascades have
                             // irradiance, and their array layers, are compiled in.
  vec4 tileDrift;            // d(landing offset per metre of depth) / d(slopes) at flat water,
                             // column-major 2x2 (tileLinearOffset)
  vec4 viewOrigin;           // xy: the view's lower-left pixel in the target (ViewDesc::viewport;
                             // 0 for a whole target); zw: unused
#ifdef __cplusplus
};
static_assert(sizeof(CausticsBlock) ==
                  2 * 64 + 11 * 16 + 3 * POSTFX_MAX_CASCADES * 16 + 3 * 16 + 6 * 16,
              "CausticsBlock must match its std140 layout");
#else
}
u;
#endif

SHARED_END

#endif
