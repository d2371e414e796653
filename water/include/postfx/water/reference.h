#pragma once
// CPU reference of the surface fields in double precision: the same modes and quantised phases
// as the GPU, transformed with a double FFT. For tests and for the accuracy reports.
#include <complex>
#include <vector>

#include <glm/glm.hpp>

#include <postfx/water/initial_spectrum.h>

namespace postfx::water {

// One cascade's fields, texel (i, j) at index j * N + i, laid out exactly like the textures:
// slope = (dh/dx, dh/dz, h, J), displacement = (Dx, h, Dz, 0).
struct SurfaceFields {
  std::vector<glm::dvec4> slope, displacement;
};

// Evaluates cascade `cascade` at the loop phase of `timeSeconds` (see loopPhase()).
SurfaceFields evaluateReference(const InitialSpectrum& spectrum, const OceanDesc& desc, int cascade,
                                double timeSeconds);

// In-place inverse DFT of a power-of-two length sequence with stride: x_n = sum_k X_k e^{+2 pi i
// n k / N} (no normalisation, the surface is a plain sum of its modes).
void inverseFft(std::complex<double>* data, int count, int stride);

}  // namespace postfx::water
