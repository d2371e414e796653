#version 450 core
// Gaussian splat of one ray's flux, added (ONE, ONE) into the caustic map.
#include "shared/common.h"
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/object_caustics/postfx_object_caustics_block.h"

flat in vec2 splatCentre;
flat in vec3 splatFlux;
flat in vec3 splatShape;  // covariance (texels^2; xx, xy, yy): see splatCovariance

layout(location = 0) out vec4 outFlux;

void main() {
  vec2 offset = gl_FragCoord.xy - splatCentre;
  // The sprite is a texel wider than +-3 sigma along the wider axis: cut each axis at its own
  // 3 sigma so that the weights sum to 1 (splatWeight).
  if (any(greaterThan(abs(offset), 3.0 * sqrt(splatShape.xz)))) discard;
  outFlux = vec4(splatFlux * splatWeight(offset, splatShape), 0.0);
}
