#version 450 core
// Metal, drawn over its own G-buffer pixels after the plugin (depth GL_EQUAL, added): what a
// metal shows is what it reflects. Its diffuse albedo in the G-buffer is baseColor *
// (1 - metallic), so the deferred lighting and the plugin's caustics give it (almost) nothing;
// this adds the environment it mirrors and the sun's highlight, Schlick-weighted by baseColor
// (glTF's F0 for metals), seen through the water between it and the camera.
#include "shared/sample_frame.h"
#include "shared/sample_optics.h"
#include "sample/water_column.glsl"
#include "sample/environment.glsl"
#include "sample/sun_shadow.glsl"
in vec3 worldNormal;
in vec3 relativePosition;
uniform vec3 baseColor;
uniform float roughness;
layout(binding = 3) uniform sampler2DShadow shadowMap;
out vec4 outColor;  // added

void main() {
  vec3 n = normalize(worldNormal);
  if (!gl_FrontFacing) n = -n;  // as the G-buffer pass: shade the side we see
  vec3 v = normalize(relativePosition);
  float height = cameraHeight.x + relativePosition.y;
  float cosV = clamp(-dot(v, n), 0.0, 1.0);
  vec3 f = baseColor + (1.0 - baseColor) * pow(1.0 - cosV, 5.0);
  // A rough metal blurs its reflection: without a prefiltered environment, lean the mirrored
  // direction toward the normal as GGX's dominant direction does.
  vec3 r = normalize(mix(reflect(v, n), n, roughness * roughness));
  vec3 reflected = f * environmentRadiance(r, height) +
                   sunSpecular(n, v, baseColor, roughness, height,
                               sunShadow(shadowMap, relativePosition, n));
  vec3 transmittance, inscatter;
  viewFog(relativePosition, transmittance, inscatter);
  outColor = vec4(reflected * transmittance, 0.0);
}
