// The per-frame uniform block of the sample host, shared by C++ and GLSL (std140).
#ifndef POSTFX_SHARED_SAMPLE_FRAME_H
#define POSTFX_SHARED_SAMPLE_FRAME_H
#include "shared/common.h"

#ifdef __cplusplus
namespace shared {
struct alignas(16) SampleFrame {
#define MAT4 glm::mat4
#define VEC4 glm::vec4
#else
layout(std140, binding = 0) uniform SampleFrame {
#define MAT4 mat4
#define VEC4 vec4
#endif
  MAT4 viewProjection;        // camera-relative world -> clip
  MAT4 cameraToWorld;         // rotation only (camera-relative world = cameraToWorld * view)
  MAT4 shadowViewProjection;  // camera-relative world -> shadow clip ([0,1] depth, forward)
  VEC4 projectionXY;          // gbuffer ProjectionParams.xy
  VEC4 projectionZ;           // xy: gbuffer ProjectionParams.z; z: depth convention; w: unused
  VEC4 cameraHeight;          // x: camera y - water level (m); yzw unused
  VEC4 sunDirection;          // xyz: unit toward the sun (world); w: 1 if above horizon
  VEC4 sunIrradiance;         // rgb: above-water irradiance at normal incidence
  VEC4 refractedSun;          // xyz: unit toward the sun as seen under water; w: 1-Fresnel
  VEC4 ambient;               // rgb: sky ambient irradiance just below the surface
  VEC4 absorption;            // rgb: 1/m
  VEC4 scattering;            // rgb: 1/m
  VEC4 waterParams;           // x: IOR; y: shadow texel size (world m); zw: the shadow map's
                              // bend above the level, x and z shift per metre of height
                              // (shadow_space.glsl; 0 0 without RenderSettings::airShadows)
  VEC4 cascadeTile[4];        // x: tile size (m), y: 1/tile, zw: camera xz offset in tiles
  VEC4 cascadeInfo;           // x: cascade count; y: exposure
};
#undef MAT4
#undef VEC4
#ifdef __cplusplus
static_assert(sizeof(SampleFrame) == 3 * 64 + 15 * 16, "std140 layout of SampleFrame");
}  // namespace shared
#endif

#endif
