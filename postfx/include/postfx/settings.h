#pragma once
// Per-frame tuning of the caustics, a plain struct with defaults. Every float must be finite
// and inside its documented range, or dispatch() returns InvalidArgument and draws nothing.

namespace postfx {

struct CausticsSettings {
  // Off: the pass is skipped (0 ms) and, with RawCausticOutput, the raw texture reads 0.
  bool enabled = true;

  // Tightening τ of ω = exp(-τ·a²) (seed 002, eq. 1), unitless, [0, 1e6]. Larger values give
  // thinner, sharper caustic lines; 0 gives ω = 1 everywhere (uniform light).
  float tau = 800.0f;

  // Blend of the reflected ray's ω into the refracted one's, [0, 1]: 0 = refraction only.
  float reflectionWeight = 0.25f;

  // Multiplier on the sun's irradiance for the added caustic light, unitless, [0, 1e4].
  float intensity = 1.0f;

  // Depth below the water level (m) over which caustics ramp in from 0 at the surface, where the
  // refracted rays have not focused yet, to full strength, [0, 1e4]. 0 = no fade.
  float surfaceFadeDepth = 1.0f;

  // Exponent sharpening the tri-planar weights |n|^k taken from the G-buffer normal, [1, 32].
  // High values make each surface use the single projection it faces most (fewest fetches).
  float triplanarSharpness = 8.0f;

  // Added to the water-texture mip level chosen from each pixel's footprint, in mip levels,
  // [-4, 8]. Positive blurs earlier with distance, which hides tile repetition sooner.
  float lodBias = 0.0f;
};

}  // namespace postfx
