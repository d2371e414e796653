#version 450 core
// Pass 1 of 2: evolves every mode of one kz row of one cascade to the current loop phase, packs
// the eight field spectra into four complex signals and transforms the row along x.
// Defines: WATER_N, WATER_LOG2_N, WATER_MODE_COUNT.
#include "shared/water_layout.h"
#include "water/fft_shared.glsl"

layout(local_size_x = WATER_N / 2) in;

layout(std430, binding = WATER_SPECTRUM_BINDING) readonly buffer Spectrum {
  vec4 amplitude[WATER_MODE_COUNT];  // (a, b): h(k, t) = a e^{-i w t} + b e^{+i w t}
  uint cycles[];                     // whole cycles per loop period
};
layout(rgba32f, binding = WATER_SCRATCH_UNIT) uniform writeonly image2DArray uScratch;

uniform uint uLoopPhase;                    // fraction of the loop elapsed, units of 2^-32
uniform float uChoppiness;                  // lambda
uniform float uWaveStep[WATER_MAX_CASCADES];  // 2 pi / tile size, rad/m

vec2 complexMul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
// F + i G for two complex spectra of real fields: the FFT output then holds f + i g.
vec2 pack(vec2 f, vec2 g) { return vec2(f.x - g.y, f.y + g.x); }
float signedFrequency(uint n) { return float(int(n) - (n < uint(WATER_N / 2) ? 0 : WATER_N)); }

void main() {
  const uint row = gl_WorkGroupID.x;  // kz index
  const uint cascade = gl_WorkGroupID.y;
  const uint tid = gl_LocalInvocationID.x;
  const float waveStep = uWaveStep[cascade];
  const float kz = signedFrequency(row) * waveStep;
  for (uint e = 0u; e < 2u; ++e) {
    const uint n = tid + e * uint(WATER_N / 2);
    const uint mode = (cascade * uint(WATER_N) + row) * uint(WATER_N) + n;
    const vec4 ab = amplitude[mode];
    // Integer phase: exact for any time, wraps exactly at the loop period.
    const float angle = float(int(cycles[mode] * uLoopPhase)) * WATER_PHASE_TO_RADIANS;
    const vec2 rotation = vec2(cos(angle), sin(angle));
    const vec2 h = complexMul(ab.xy, vec2(rotation.x, -rotation.y)) + complexMul(ab.zw, rotation);
    const vec2 ih = vec2(-h.y, h.x);
    const float kx = signedFrequency(n) * waveStep;
    const float k = length(vec2(kx, kz));
    const float chop = k > 0.0 ? uChoppiness / k : 0.0;
    const uint slot = bitReversed(n);
    lineA[slot] = vec4(pack(h, kx * ih), pack(kz * ih, chop * kx * ih));
    lineB[slot] = vec4(pack(chop * kz * ih, -chop * kx * kx * h),
                       pack(-chop * kz * kz * h, -chop * kx * kz * h));
  }
  inverseFftLine(tid);
  for (uint e = 0u; e < 2u; ++e) {
    const uint n = tid + e * uint(WATER_N / 2);
    const int layer = int(cascade) * WATER_SCRATCH_LAYERS_PER_CASCADE;
    imageStore(uScratch, ivec3(n, row, layer), lineA[n]);
    imageStore(uScratch, ivec3(n, row, layer + 1), lineB[n]);
  }
}
