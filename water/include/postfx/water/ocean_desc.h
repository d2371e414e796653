#pragma once
// Everything that defines an ocean surface: the wave spectrum, the cascades that tile it and the
// loop period of its animation. Fixed for an Ocean's life; validate with validateOceanDesc().
#include <array>
#include <cstdint>
#include <string>

#include <postfx/water/result.h>

namespace postfx::water {

inline constexpr int kMaxCascades = 4;
inline constexpr int kMaxResolution = 512;
inline constexpr double kGravity = 9.81;  // m/s^2

struct OceanDesc {
  // FFT grid size per cascade, texels per side. Power of two in [8, 512].
  int resolution = 256;

  // Number of cascades in [1, kMaxCascades]. Cascade c is a tile of tileSize[c] metres; sizes
  // must strictly decrease. Non-integer ratios keep the tiles' repeat from lining up. Each
  // cascade keeps only the wavenumber band no other cascade covers (see cascadeBands()), so
  // energy is never counted twice. Needs tileSize[c] / tileSize[c+1] < resolution / 2.
  int cascadeCount = 3;
  std::array<double, kMaxCascades> tileSize = {250.0, 37.0, 5.3, 1.0};  // m

  // JONSWAP spectrum (Hasselmann et al. 1973).
  double windSpeed = 10.0;       // m/s at 10 m height, [0, 60]; 0 gives a flat, calm sea
  double windDirection = 0.0;    // radians, direction the wind blows toward, from +x toward +z
  double fetch = 100000.0;       // m, distance over which the wind has blown, [1e2, 1e7]
  double peakEnhancement = 3.3;  // JONSWAP gamma, [1, 20]; 1 is Pierson-Moskowitz-like
  // Directional spreading exponent s of D(theta) ~ |cos(theta/2)|^(2s) (Longuet-Higgins),
  // [0, 200]; 0 is isotropic, larger is more aligned with the wind.
  double spreading = 8.0;

  double choppiness = 1.0;  // horizontal displacement scale lambda, [0, 4]; 0 is no chop
  double depth = 0.0;       // m, water depth for the dispersion relation; 0 means deep water

  // Every wave's frequency is rounded to a multiple of 2*pi/loopPeriod, so the surface at
  // t and t + loopPeriod is the same. Seconds, [1, 1e6].
  double loopPeriod = 600.0;

  // Seed of the deterministic random amplitudes (same seed, same sea, bit for bit).
  uint64_t seed = 0x5EA5EEDull;
};

// Checks every field against its documented range. Returns Ok, or InvalidArgument with a message
// naming the field. Does not consult GL (Ocean::create checks the driver's limits).
Result validateOceanDesc(const OceanDesc& desc, std::string& error);

}  // namespace postfx::water
