#include <postfx/water/spectrum.h>

#include <postfx/water/initial_spectrum.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace postfx::water {
namespace {

constexpr double kPi = std::numbers::pi;

bool isDeep(double depth) {
  return !(depth > 0.0);
}

}  // namespace

double dispersion(double k, double depth) {
  if (!(k > 0.0)) return 0.0;
  // tanh(kd) is 1 to double precision beyond kd ~ 20; skipping it avoids nothing but cost.
  const double shallow = isDeep(depth) ? 1.0 : std::tanh(k * depth);
  return std::sqrt(kGravity * k * shallow);
}

double dispersionDerivative(double k, double depth) {
  const double omega = dispersion(k, depth);
  if (!(omega > 0.0)) return 0.0;
  if (isDeep(depth)) return kGravity / (2.0 * omega);
  const double kd = k * depth;
  const double t = std::tanh(kd);
  const double sech2 = 1.0 - t * t;
  return kGravity * (t + kd * sech2) / (2.0 * omega);
}

double jonswap(double omega, const OceanDesc& desc) {
  const double wind = desc.windSpeed;
  if (!(omega > 0.0) || !(wind > 0.0)) return 0.0;
  const double g = kGravity;
  // Hasselmann et al. 1973 fetch-limited fits for the Phillips constant and the peak frequency.
  const double alpha = 0.076 * std::pow(wind * wind / (desc.fetch * g), 0.22);
  const double peak = 22.0 * std::cbrt(g * g / (wind * desc.fetch));
  const double sigma = omega <= peak ? 0.07 : 0.09;
  const double ratio = peak / omega;
  const double ratio4 = ratio * ratio * ratio * ratio;
  // exp(-1.25 ratio^4) underflows to exactly 0 far below the peak: that is the right limit.
  const double base = alpha * g * g / std::pow(omega, 5.0) * std::exp(-1.25 * ratio4);
  const double offset = (omega - peak) / (sigma * peak);
  const double enhancement = std::pow(desc.peakEnhancement, std::exp(-0.5 * offset * offset));
  return base * enhancement;
}

double directionalSpreading(double theta, double s) {
  // Normalisation of |cos(theta/2)|^(2s) over [-pi, pi]: 2^(2s-1) Gamma(s+1)^2 / (pi
  // Gamma(2s+1)), in logs so large s does not overflow.
  const double logNorm = (2.0 * s - 1.0) * std::log(2.0) + 2.0 * std::lgamma(s + 1.0) -
                         std::lgamma(2.0 * s + 1.0) - std::log(kPi);
  const double c = std::abs(std::cos(0.5 * theta));
  if (s == 0.0) return std::exp(logNorm);
  if (!(c > 0.0)) return 0.0;
  return std::exp(logNorm + 2.0 * s * std::log(c));
}

double waveSpectrum(double kx, double kz, const OceanDesc& desc) {
  const double k = std::hypot(kx, kz);
  if (!(k > 0.0)) return 0.0;
  const double omega = dispersion(k, desc.depth);
  const double theta = std::atan2(kz, kx) - desc.windDirection;
  // S(k) d^2k = S(omega) D(theta) d(omega) d(theta), and d^2k = k dk d(theta).
  return jonswap(omega, desc) * dispersionDerivative(k, desc.depth) / k *
         directionalSpreading(theta, desc.spreading);
}

std::vector<CascadeBand> cascadeBands(const OceanDesc& desc) {
  std::vector<CascadeBand> bands(static_cast<size_t>(desc.cascadeCount));
  const double n = desc.resolution;
  double lower = 0.0;
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const double nyquist = kPi * n / desc.tileSize[c];
    double upper = nyquist;
    if (c + 1 < desc.cascadeCount) {
      // Hand over halfway (geometrically) between the finer tile's fundamental and this tile's
      // Nyquist: both grids then sample the boundary region with many modes.
      const double finerFundamental = 2.0 * kPi / desc.tileSize[c + 1];
      upper = std::sqrt(finerFundamental * nyquist);
    }
    bands[c] = {lower, upper};
    lower = upper;
  }
  return bands;
}

std::vector<CascadeWaveStats> cascadeWaveStats(const OceanDesc& desc) {
  const std::vector<CascadeBand> bands = cascadeBands(desc);
  const int n = desc.resolution;
  std::vector<CascadeWaveStats> stats(bands.size());
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const double dk = 2.0 * kPi / desc.tileSize[c];
    double slope2 = 0.0, laplacian2 = 0.0;
    for (int m = 0; m < n; ++m) {
      for (int i = 0; i < n; ++i) {
        const int si = signedFrequency(i, n), sm = signedFrequency(m, n);
        if (si == -n / 2 || sm == -n / 2) continue;
        const double kx = si * dk, kz = sm * dk;
        const double k = std::hypot(kx, kz);
        if (!(k >= bands[c].kMin && k < bands[c].kMax) || k == 0.0) continue;
        const double variance = waveSpectrum(kx, kz, desc) * dk * dk;
        slope2 += k * k * variance;
        laplacian2 += k * k * k * k * variance;
      }
    }
    stats[c].rmsSlope = std::sqrt(slope2);
    stats[c].rmsLaplacian = std::sqrt(laplacian2);
    stats[c].longestWavelength = 2.0 * kPi / std::max(bands[c].kMin, dk);
  }
  return stats;
}

double discreteMeanSquareSlope(const OceanDesc& desc) {
  double sum = 0.0;
  for (const CascadeWaveStats& cascade : cascadeWaveStats(desc)) {
    sum += cascade.rmsSlope * cascade.rmsSlope;
  }
  return sum;
}

double integratedMeanSquareSlope(const OceanDesc& desc) {
  const std::vector<CascadeBand> bands = cascadeBands(desc);
  const double kMax = bands.back().kMax;
  // Simpson in log k from far below any peak: the integrand k^3 S_iso(k) is smooth there.
  const double logLo = std::log(1e-5), logHi = std::log(kMax);
  const int steps = 20000;
  const double h = (logHi - logLo) / steps;
  double sum = 0.0;
  for (int i = 0; i <= steps; ++i) {
    const double k = std::exp(logLo + i * h);
    const double omega = dispersion(k, desc.depth);
    // k^2 * S_iso(k) * k dk, with dk = k d(log k) and S_iso = S(omega) omega' / k.
    const double f = k * k * jonswap(omega, desc) * dispersionDerivative(k, desc.depth) * k;
    const double weight = (i == 0 || i == steps) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += weight * f;
  }
  return sum * h / 3.0;
}

}  // namespace postfx::water
