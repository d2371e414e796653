#pragma once
// Water surfaces with known answers for the CPU references' tests (seabed light tracer, traced
// frame reference), and the flux a sine wave must deliver.
#include <cmath>

#include "seabed_reference.h"

namespace referencetest {

inline constexpr double kPi = 3.141592653589793;

class FlatSurface final : public ocean::reference::Surface {
 public:
  ocean::reference::SurfaceSample sample(double, double) const override { return {}; }
  double maxHeight() const override { return 0.0; }
  double maxSlope() const override { return 0.0; }
  double featureSize() const override { return 1.0; }
};

// h = amplitude * sin(k x): crests along z.
class SineSurface final : public ocean::reference::Surface {
 public:
  SineSurface(double amplitude, double wavelength)
      : amplitude_(amplitude), k_(2.0 * kPi / wavelength), wavelength_(wavelength) {}
  // The wave whose steepest slope is `slope`.
  static SineSurface withSlope(double slope, double wavelength) {
    return SineSurface(slope * wavelength / (2.0 * kPi), wavelength);
  }
  ocean::reference::SurfaceSample sample(double x, double) const override {
    return {amplitude_ * std::sin(k_ * x), amplitude_ * k_ * std::cos(k_ * x), 0.0};
  }
  double maxHeight() const override { return amplitude_; }
  double maxSlope() const override { return amplitude_ * k_; }
  double featureSize() const override { return wavelength_ / 64.0; }
  double k() const { return k_; }

 private:
  double amplitude_, k_, wavelength_;
};

// The mean irradiance a wave with crests along z gives over whole periods under a vertical sun:
// the beam's cross-section per horizontal area is 1 everywhere, so it is the Fresnel
// transmittance relative to flat water, averaged over `period` (m) of x.
inline double meanTransmittanceRatio(const ocean::reference::Surface& surface, double period,
                                     double ior) {
  const double flat = ocean::reference::fresnelTransmittance(1.0, ior);
  double sum = 0.0;
  const int samples = 100000;
  for (int i = 0; i < samples; ++i) {
    const double s = surface.sample((i + 0.5) / samples * period, 0.0).slopeX;
    sum += ocean::reference::fresnelTransmittance(1.0 / std::sqrt(1.0 + s * s), ior) / flat;
  }
  return sum / samples;
}

}  // namespace referencetest
