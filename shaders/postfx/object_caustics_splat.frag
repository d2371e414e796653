#version 450 core
// Gaussian splat of one ray's flux, added (ONE, ONE) into the caustic map.
#include "shared/common.h"
#include "shared/postfx_object_caustics.h"
#include "shared/postfx_object_caustics_block.h"

flat in vec2 splatCentre;
flat in vec3 splatFlux;
flat in float splatSigma;  // map texels: splatRadius, widened for rough casters

layout(location = 0) out vec4 outFlux;

void main() {
  vec2 offset = gl_FragCoord.xy - splatCentre;
  float sigma = splatSigma;
  // The sprite is a texel wider than +-3 sigma: cut it there so the weights sum to 1.
  if (any(greaterThan(abs(offset), vec2(3.0 * sigma)))) discard;
  outFlux = vec4(splatFlux * splatWeight(offset, sigma), 0.0);
}
