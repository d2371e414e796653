// The CPU reference: its FFT against a plain DFT, and its fields against a direct sum of the
// waves, which pins down the texel position, sign and derivative conventions of the contract.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>

#include <postfx/water/random.h>
#include <postfx/water/reference.h>

namespace {

using Complex = std::complex<double>;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

TEST(WaterReference, FftMatchesPlainDft) {
  const int n = 32;
  postfx::water::GaussianRandom random(7);
  std::vector<Complex> data(n);
  for (auto& value : data) {
    double re = 0.0, im = 0.0;
    random.nextPair(re, im);
    value = {re, im};
  }
  std::vector<Complex> fast = data;
  postfx::water::inverseFft(fast.data(), n, 1);
  for (int x = 0; x < n; ++x) {
    Complex sum;
    for (int k = 0; k < n; ++k) sum += data[k] * std::polar(1.0, kTwoPi * x * k / n);
    EXPECT_NEAR(std::abs(fast[x] - sum), 0.0, 1e-12);
  }
}

// Texel (i, j) must hold the sum of every wave at world ((i + 0.5), (j + 0.5)) * L / N, and that
// sum must be real (the spectrum is Hermitian).
TEST(WaterReference, FieldsEqualTheDirectSumOfWaves) {
  postfx::water::OceanDesc desc;
  desc.resolution = 16;
  desc.cascadeCount = 2;
  desc.tileSize = {40.0, 7.3, 0.0, 0.0};
  desc.choppiness = 1.3;
  const double time = 123.456;
  const auto spectrum = postfx::water::buildInitialSpectrum(desc);
  const int n = desc.resolution;
  const double omegaStep = kTwoPi / desc.loopPeriod;
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const auto fields = postfx::water::evaluateReference(spectrum, desc, c, time);
    const double size = desc.tileSize[c], dk = kTwoPi / size;
    for (int j : {0, 5, 15}) {
      for (int i : {0, 3, 8}) {
        // The contract: texel (i, j) is the sea at ((i + 0.5), (j + 0.5)) * L / N. Undo the
        // half-texel shift the stored amplitudes carry and evaluate the waves there.
        const double halfTexel = 0.5 * size / n;
        const double x = (i + 0.5) * size / n, z = (j + 0.5) * size / n;
        Complex h, hx, dx, dxx, dzz, dxz;
        for (int m = 0; m < n; ++m) {
          for (int p = 0; p < n; ++p) {
            const size_t mode = spectrum.index(c, p, m);
            const double kx = postfx::water::signedFrequency(p, n) * dk;
            const double kz = postfx::water::signedFrequency(m, n) * dk;
            const double k = std::hypot(kx, kz);
            const double w = spectrum.cycles[mode] * omegaStep;
            const Complex amplitude = spectrum.a[mode] * std::polar(1.0, -w * time) +
                                      spectrum.b[mode] * std::polar(1.0, w * time);
            const Complex unshifted = amplitude * std::polar(1.0, -(kx + kz) * halfTexel);
            const Complex wave = unshifted * std::polar(1.0, kx * x + kz * z);
            const double inv = k > 0 ? desc.choppiness / k : 0.0;
            h += wave;
            hx += Complex(0, kx) * wave;
            dx += Complex(0, kx * inv) * wave;
            dxx -= kx * kx * inv * wave;
            dzz -= kz * kz * inv * wave;
            dxz -= kx * kz * inv * wave;
          }
        }
        const auto slope = fields.slope[static_cast<size_t>(j) * n + i];
        const auto displacement = fields.displacement[static_cast<size_t>(j) * n + i];
        // Time differs by the 2^-32 loop rounding: ~1e-7 s, far below these tolerances.
        EXPECT_NEAR(h.imag(), 0.0, 1e-12);
        EXPECT_NEAR(slope.z, h.real(), 1e-7);
        EXPECT_NEAR(slope.x, hx.real(), 1e-7);
        EXPECT_NEAR(displacement.x, dx.real(), 1e-7);
        EXPECT_NEAR(displacement.y, h.real(), 1e-7);
        const double jacobian = (1 + dxx.real()) * (1 + dzz.real()) - dxz.real() * dxz.real();
        EXPECT_NEAR(slope.w, jacobian, 1e-7);
      }
    }
  }
}

}  // namespace
