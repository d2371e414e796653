#pragma once
// The random initial amplitudes and quantised frequencies of every mode of every cascade, built
// deterministically on the CPU in double. Both the GPU path and the CPU reference start here.
#include <complex>
#include <cstdint>
#include <vector>

#include <postfx/water/ocean_desc.h>

namespace postfx::water {

// Mode (n, m) of cascade c, stored at index (c * N + m) * N + n, is the wave vector
// k = 2 pi / L_c * (n', m') with n' = n for n < N/2 and n - N otherwise (FFT order).
// Its complex height amplitude at time t is
//   h(k, t) = a * exp(-i w t) + b * exp(+i w t),   w = 2 pi cycles / loopPeriod,
// where a = h0(k) e^{i k.d} and b = conj(h0(-k)) e^{i k.d}, with d = (L/2N, L/2N): the half-texel
// shift that puts texel (i, j) at world (i + 0.5, j + 0.5) * L / N. The Nyquist row and column,
// k = 0 and every mode outside the cascade's band are zero.
struct InitialSpectrum {
  int resolution = 0;
  int cascadeCount = 0;
  std::vector<std::complex<double>> a, b;
  std::vector<uint32_t> cycles;  // whole cycles per loop period (quantised frequency)

  size_t index(int cascade, int n, int m) const {
    return (static_cast<size_t>(cascade) * resolution + m) * resolution + n;
  }
};

// Requires a desc that validateOceanDesc() accepts.
InitialSpectrum buildInitialSpectrum(const OceanDesc& desc);

// Signed FFT frequency index of grid index n.
inline int signedFrequency(int n, int resolution) {
  return n < resolution / 2 ? n : n - resolution;
}

// Time reduced to the loop: the fraction of the loop period elapsed, in units of 2^-32. Computed
// in double (fmod is exact), so t = 1e7 s is as precise as t = 0. A wave with `cycles` cycles per
// loop has phase 2 pi (cycles * loopPhase mod 2^32) / 2^32 -- integer arithmetic, exact on the
// GPU too. Requires a finite time.
uint32_t loopPhase(double timeSeconds, double loopPeriod);

}  // namespace postfx::water
