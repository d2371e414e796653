#include <postfx/water/initial_spectrum.h>

#include <cmath>
#include <numbers>

#include <postfx/water/random.h>
#include <postfx/water/spectrum.h>

namespace postfx::water {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// h0(k) for every grid index of one cascade, drawn in a fixed order (every index, in band or
// not) so the band layout never shifts the random stream of the modes that remain.
std::vector<std::complex<double>> drawAmplitudes(const OceanDesc& desc, int cascade,
                                                 const CascadeBand& band) {
  const int n = desc.resolution;
  const double dk = kTwoPi / desc.tileSize[cascade];
  GaussianRandom random(desc.seed ^ (0x9E3779B97F4A7C15ull * static_cast<uint64_t>(cascade + 1)));
  std::vector<std::complex<double>> h0(static_cast<size_t>(n) * n);
  for (int m = 0; m < n; ++m) {
    for (int i = 0; i < n; ++i) {
      double re = 0.0, im = 0.0;
      random.nextPair(re, im);
      const int si = signedFrequency(i, n), sm = signedFrequency(m, n);
      // The Nyquist line has no partner -k on the grid; a real field cannot carry it.
      if (si == -n / 2 || sm == -n / 2) continue;
      const double kx = si * dk, kz = sm * dk;
      const double k = std::hypot(kx, kz);
      if (k == 0.0 || !(k >= band.kMin && k < band.kMax)) continue;
      // E|h0|^2 = S dk^2 / 2, so that E[h^2] = sum_k S(k) dk^2 once h0(-k) joins in.
      const double scale = 0.5 * std::sqrt(waveSpectrum(kx, kz, desc)) * dk;
      h0[static_cast<size_t>(m) * n + i] = {re * scale, im * scale};
    }
  }
  return h0;
}

}  // namespace

InitialSpectrum buildInitialSpectrum(const OceanDesc& desc) {
  InitialSpectrum spectrum;
  const int n = desc.resolution;
  spectrum.resolution = n;
  spectrum.cascadeCount = desc.cascadeCount;
  const size_t total = static_cast<size_t>(n) * n * desc.cascadeCount;
  spectrum.a.assign(total, {});
  spectrum.b.assign(total, {});
  spectrum.cycles.assign(total, 0);
  const std::vector<CascadeBand> bands = cascadeBands(desc);
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const std::vector<std::complex<double>> h0 = drawAmplitudes(desc, c, bands[c]);
    const double dk = kTwoPi / desc.tileSize[c];
    const double halfTexel = 0.5 * desc.tileSize[c] / n;
    for (int m = 0; m < n; ++m) {
      for (int i = 0; i < n; ++i) {
        const int si = signedFrequency(i, n), sm = signedFrequency(m, n);
        const size_t self = static_cast<size_t>(m) * n + i;
        const size_t mirror = static_cast<size_t>((n - m) % n) * n + (n - i) % n;
        const double kx = si * dk, kz = sm * dk;
        const std::complex<double> shift = std::polar(1.0, (kx + kz) * halfTexel);
        const size_t out = spectrum.index(c, i, m);
        spectrum.a[out] = h0[self] * shift;
        spectrum.b[out] = std::conj(h0[mirror]) * shift;
        // Whole cycles per loop: rounding w T / 2 pi makes every wave repeat after T exactly.
        const double omega = dispersion(std::hypot(kx, kz), desc.depth);
        spectrum.cycles[out] =
            static_cast<uint32_t>(std::llround(omega * desc.loopPeriod / kTwoPi));
      }
    }
  }
  return spectrum;
}

uint32_t loopPhase(double timeSeconds, double loopPeriod) {
  double fraction = std::fmod(timeSeconds, loopPeriod) / loopPeriod;
  if (fraction < 0.0) fraction += 1.0;
  // Round to 2^-32 of the period (~1e-7 s for a 600 s loop); wraps 1.0 to 0.
  const uint64_t units = static_cast<uint64_t>(std::llround(fraction * 0x1.0p32));
  return static_cast<uint32_t>(units & 0xFFFFFFFFull);
}

}  // namespace postfx::water
