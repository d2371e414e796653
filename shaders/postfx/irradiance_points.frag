#version 450 core
// Wavefront area-ratio caustics (seed 004), points: a sub-texel triangle's flux into one texel
// (irradiance = flux / texel area, the texel being the unit of area).
#include "postfx/irradiance_count.glsl"

flat in float keptFlux;
flat in float removedFlux;

layout(location = 0) out float outIrradiance;

void main() {
  countRemoved(removedFlux);
  outIrradiance = keptFlux;
}
