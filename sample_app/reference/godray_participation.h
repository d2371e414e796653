#pragma once
// The god rays' share of the light with depth, rho of shaders/postfx/god_rays/postfx_godrays.h
// (godRayParticipation), in double: the god-ray and the volume-caustics references weigh their
// in-scattering by it as the plugin does.
#include <algorithm>
#include <cmath>

namespace ocean::reference {

// Smooth fade-in over `surfaceFade` metres below the level times exp(-depth / depthFade); 0 above
// the water or for NaN.
inline double godRayParticipation(double depthBelow, double surfaceFade, double depthFade) {
  if (!(depthBelow > 0.0)) return 0.0;
  double rho = 1.0;
  if (surfaceFade > 0.0) {
    const double t = std::clamp(depthBelow / surfaceFade, 0.0, 1.0);
    rho = t * t * (3.0 - 2.0 * t);
  }
  if (depthFade > 0.0) rho *= std::exp(-depthBelow / depthFade);
  return rho;
}

}  // namespace ocean::reference
