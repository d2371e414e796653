#version 450 core
// Underwater fog: extinction and in-scattering along the part of each view ray below the
// (flat) water plane. Runs BEFORE the plugin adds its light: the plugin attenuates what it adds
// itself (postfx::ViewExtinction::Plugin), so fogging it again would count the extinction twice.
#include "shared/gbuffer_codec.h"
#include "shared/sample_frame.h"
#include "shared/sample_optics.h"
#include "sample/reconstruct.glsl"
#include "sample/water_column.glsl"
in vec2 uv;
layout(binding = 0) uniform sampler2D depthTexture;
layout(binding = 1) uniform sampler2D radianceTexture;
out vec4 outRadiance;
void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec3 radiance = texelFetch(radianceTexture, pixel, 0).rgb;
  float depth = texelFetch(depthTexture, pixel, 0).r;
  if (isSkyDepth(depth, int(projectionZ.z))) {
    // Nothing was drawn. A ray that enters the water and meets no geometry (past the seabed's
    // edge, or level under water) sees infinitely deep water: pure in-scattering. From above,
    // the surface pass then blends its reflection over it; from below it covers what it hits.
    // Under water the lighting pass wrote 0 here; the plugin's god rays are added afterwards.
    bool entersWater = cameraHeight.x < 0.0 || viewDirection(uv).y < 0.0;
    outRadiance = vec4(entersWater ? deepWaterColour() : radiance, 1.0);
    return;
  }
  vec3 transmittance, inscatter;
  viewFog(reconstructRelative(uv, depth), transmittance, inscatter);
  outRadiance = vec4(radiance * transmittance + inscatter, 1.0);
}
