// Radix-2 inverse FFT of one line of WATER_N modes held in shared memory, two RGBA32F texels
// (four complex signals) per mode. One workgroup of WATER_N / 2 invocations per line: each
// invocation does one butterfly per stage, in place (Cooley-Tukey, decimation in time), so the
// caller loads the line in bit-reversed order and reads it back in natural order.
#ifndef WATER_FFT_SHARED_GLSL
#define WATER_FFT_SHARED_GLSL

const float WATER_PI = 3.14159265358979;

shared vec4 lineA[WATER_N];
shared vec4 lineB[WATER_N];

uint bitReversed(uint index) { return bitfieldReverse(index) >> (32u - uint(WATER_LOG2_N)); }

// Two complex numbers (xy, zw) times one complex w.
vec4 complexScale(vec4 v, vec2 w) {
  return vec4(v.x * w.x - v.y * w.y, v.x * w.y + v.y * w.x, v.z * w.x - v.w * w.y,
              v.z * w.y + v.w * w.x);
}

// x_n = sum_k X_k exp(+2 pi i n k / N), unnormalised (the surface is the plain sum of modes).
void inverseFftLine(uint tid) {
  for (uint span = 1u; span < uint(WATER_N); span <<= 1) {
    memoryBarrierShared();
    barrier();
    const uint pos = tid & (span - 1u);
    const uint i = ((tid - pos) << 1) + pos;
    const uint j = i + span;
    // Twiddle from its angle, not a running product, so error does not grow along the line.
    const float angle = WATER_PI * float(pos) / float(span);
    const vec2 w = vec2(cos(angle), sin(angle));
    const vec4 a0 = lineA[i], a1 = complexScale(lineA[j], w);
    const vec4 b0 = lineB[i], b1 = complexScale(lineB[j], w);
    lineA[i] = a0 + a1;
    lineA[j] = a0 - a1;
    lineB[i] = b0 + b1;
    lineB[j] = b0 - b1;
  }
  memoryBarrierShared();
  barrier();
}

#endif
