#version 450 core
// The water surface seen from above (Fresnel mix of sky reflection and the fogged scene below,
// through blending) and from below (Snell's window; total internal reflection outside it).
#include "shared/sample_frame.h"
#include "shared/sample_optics.h"
in vec2 surfaceXZ;
in vec3 relativePosition;
layout(binding = 5) uniform sampler2DArray slopes;
out vec4 outColor;  // blended as rgb + destination * (1 - a)

vec3 surfaceNormal() {
  vec2 slope = vec2(0.0);
  int count = int(cascadeInfo.x);
  for (int c = 0; c < count; ++c) {
    slope += texture(slopes, vec3(surfaceXZ * cascadeTile[c].y + cascadeTile[c].zw, float(c))).xy;
  }
  return normalize(vec3(-slope.x, 1.0, -slope.y));
}

void main() {
  vec3 n = surfaceNormal();
  vec3 view = normalize(relativePosition);  // camera -> surface
  float ior = waterParams.x;
  vec3 sigmaT = absorption.rgb + scattering.rgb;
  vec3 deepColor = waterInscatter(scattering.rgb, sigmaT, ambient.rgb, 0.0);
  // Which side we look from is the camera's side of the water, not the triangle's facing: from
  // below, the back of a far crest faces us and must still read as seen from below.
  if (cameraHeight.x >= 0.0) {
    // From above: reflect the sky; the scene below (already fogged) shows through with 1 - F.
    vec3 r = reflect(view, n);
    r.y = abs(r.y);  // a grazing reflection into a wave's back still sees sky, not the seabed
    float f = fresnelReflectance(max(-dot(view, n), 0.0), 1.0, ior);
    outColor = vec4(skyRadiance(normalize(r), sunDirection.xyz) * f, f);
    return;
  }
  // From below: the surface normal faces away from us. Outside Snell's window F = 1 (total
  // internal reflection) and we see the deep water reflected.
  vec3 nb = -n;
  float f = fresnelReflectance(max(-dot(view, nb), 0.0), ior, 1.0);
  vec3 sky = vec3(0.0);
  if (f < 1.0) sky = skyRadiance(normalize(refract(view, nb, ior)), sunDirection.xyz);
  vec3 color = (1.0 - f) * sky + f * deepColor;
  vec3 transmittance = exp(-sigmaT * length(relativePosition));
  outColor = vec4(color * transmittance + deepColor * (1.0 - transmittance), 1.0);
}
