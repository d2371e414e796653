#pragma once
// The wave spectrum in double precision: dispersion, JONSWAP, directional spreading, the
// wavenumber band each cascade owns and the analytic mean-square slope. Pure CPU math.
#include <vector>

#include <postfx/water/ocean_desc.h>

namespace postfx::water {

// Angular frequency (rad/s) of a wave of wavenumber k (rad/m): sqrt(g k tanh(k d)), deep water
// (sqrt(g k)) when depth <= 0.
double dispersion(double k, double depth);
// d(omega)/dk, group velocity (m/s).
double dispersionDerivative(double k, double depth);

// JONSWAP frequency spectrum S(omega), m^2 s. Zero for omega <= 0 or windSpeed == 0.
double jonswap(double omega, const OceanDesc& desc);

// Normalised directional spreading D(theta) (1/rad), integral over [-pi, pi] is 1. `theta` is
// relative to the wind direction.
double directionalSpreading(double theta, double s);

// Directional wavenumber spectrum S(kx, kz), m^4: the variance of h is the integral over the
// wavenumber plane. S(k) = S(omega(k)) * domega/dk / |k| * D(theta - windDirection).
double waveSpectrum(double kx, double kz, const OceanDesc& desc);

// The |k| band a cascade owns: kMin <= |k| < kMax (rad/m). Bands of neighbours share their
// boundary, the first starts at 0 and the last ends at its Nyquist wavenumber pi N / L, so the
// union is a single interval and no wave is counted twice.
struct CascadeBand {
  double kMin, kMax;
};
std::vector<CascadeBand> cascadeBands(const OceanDesc& desc);

// Expected mean-square Lagrangian slope E[(dh/dx)^2 + (dh/dz)^2] of the whole sea as the
// cascades discretise it: sum over every mode of |k|^2 S(k) dk^2.
double discreteMeanSquareSlope(const OceanDesc& desc);
// The same as an integral of the continuous spectrum over the covered band (isotropic part only:
// the spreading integrates to one over the full circle). The physics reference.
double integratedMeanSquareSlope(const OceanDesc& desc);

// What a renderer needs to know about one cascade's waves to decide whether a pixel can see
// them at all (postfx::WaterSurface carries these to the caustics and god rays).
struct CascadeWaveStats {
  // sqrt(E[(dh/dx)^2 + (dh/dz)^2]) over the cascade's modes (unitless).
  double rmsSlope = 0.0;
  // sqrt(E[(laplacian h)^2]) (1/m). Light refracted into water of index n through this
  // curvature alone focuses, to first order, at a path length n / ((n - 1) * rmsLaplacian).
  double rmsLaplacian = 0.0;
  // Longest wavelength the cascade holds (m): 2 pi / max(kMin, its tile's fundamental).
  double longestWavelength = 0.0;
};
// One entry per cascade, summed over the same discrete modes the FFT holds.
std::vector<CascadeWaveStats> cascadeWaveStats(const OceanDesc& desc);

}  // namespace postfx::water
