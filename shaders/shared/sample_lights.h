// The sample host's point and spot lights for its deferred lighting, shared by C++ and GLSL
// (std140, binding 1). Positions are camera-relative (reduced in double on the CPU).
#ifndef POSTFX_SHARED_SAMPLE_LIGHTS_H
#define POSTFX_SHARED_SAMPLE_LIGHTS_H
#include "shared/common.h"

#define SAMPLE_MAX_LIGHTS 4

#ifdef __cplusplus
namespace shared {
struct alignas(16) SampleLights {
#define MAT4 glm::mat4
#define VEC4 glm::vec4
#else
layout(std140, binding = 1) uniform SampleLights {
#define MAT4 mat4
#define VEC4 vec4
#endif
  MAT4 lightViewProjection[SAMPLE_MAX_LIGHTS];  // camera-relative world -> light clip
  VEC4 lightPosition[SAMPLE_MAX_LIGHTS];        // xyz: camera-relative (m); w: 1 spot, 0 point
  VEC4 lightAxis[SAMPLE_MAX_LIGHTS];            // xyz: unit axis of a spot; w: unused
  VEC4 lightIntensity[SAMPLE_MAX_LIGHTS];       // rgb: irradiance at 1 m; w: light's height above
                                                // the water (m)
  VEC4 lightCone[SAMPLE_MAX_LIGHTS];  // x: half-angle, y: angle where the fade starts (rad);
                                      // z: shadow texel size per metre of distance
  VEC4 lightCount;                    // x: lights in use
};
#undef MAT4
#undef VEC4
#ifdef __cplusplus
static_assert(sizeof(SampleLights) == SAMPLE_MAX_LIGHTS * (64 + 4 * 16) + 16,
              "std140 layout of SampleLights");
}  // namespace shared
#endif

#endif
