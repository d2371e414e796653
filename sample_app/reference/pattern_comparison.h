#pragma once
// How well a method's caustic *pattern* matches the traced one: each side's added light divided
// by flat water's added light at the same pixel. The whole added light shares albedo, N.L,
// shadow, depth absorption and view extinction between the two sides, which lift a whole-frame
// correlation whatever the pattern does; the ratio removes them and leaves the irradiance
// relative to flat water (1 under a calm sea, waves only redistribute it).
//
// Pixels: those of `mask` (the traced frame's lit underwater pixels) whose flat added light is
// at least a quarter of its median over the mask (the darkest, grazing or penumbral pixels make
// the ratio ill-conditioned).
//
// Sharpness: the radially averaged power spectrum of each pattern over one square screen patch
// (the largest power-of-two square, 32..256 pixels, whose pixels are almost all compared; the
// pattern minus its mean under a Hann window), summed per octave of spatial frequency and
// divided, method over reference. Above 1 in the fine octaves the method is sharper (or has
// detail the trace lacks: rings, moire, a texel grid), below 1 softer. The finest octave (periods
// of 2-4 pixels) holds the trace's Monte Carlo noise and its kernel's smoothing, so the verdict
// reads the octaves of 4 pixels and more; a narrow peak the trace lacks is the largest ratio of
// one quarter-octave band to the octave around it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace ocean::reference {

struct SpectrumOctave {
  double minPeriodPixels = 0.0, maxPeriodPixels = 0.0;  // the band's periods
  double methodPower = 0.0, referencePower = 0.0;       // summed over the band
  double ratio = 0.0;  // method / reference (0: no reference power)
};

struct PatternSpectrum {
  int patchX = 0, patchY = 0, patchSize = 0;  // top-left corner, top row first; 0: no patch
  std::vector<SpectrumOctave> octaves;        // coarsest first
  // Geometric mean of the ratios over the octaves with periods of 4 to 64 pixels (the pattern's
  // scale at the resolutions compared); 1 when the method is as sharp as the trace.
  double fineRatio = 0.0;
  // Largest quarter-octave band power ratio (method / reference) divided by the mean ratio of
  // the octave around that band, over periods of 4 pixels and more: a ring or grid the method
  // draws and the trace does not puts a narrow peak there (1 for matching spectra).
  double peak = 0.0;
  double peakPeriodPixels = 0.0;
  // "too soft", "too sharp" or "as sharp" from fineRatio (outside [0.7, 1.4] is off).
  std::string verdict;
};

struct PatternComparison {
  size_t pixels = 0;  // compared
  double flatMedian = 0.0;
  double correlation = 0.0;   // Pearson's r of the two patterns
  double relativeRmse = 0.0;  // sqrt(sum (m - r)^2 / sum r^2) of the patterns
  double methodMean = 0.0, referenceMean = 0.0;
  double methodContrast = 0.0, referenceContrast = 0.0;  // std / mean
  double methodP99 = 0.0, referenceP99 = 0.0;            // 99th percentile of the pattern
  PatternSpectrum spectrum;
  // Per pixel (width * height, top row first as the inputs): the patterns, 0 where not compared.
  std::vector<double> methodPattern, referencePattern;
  std::vector<std::uint8_t> compared;
};

// method, reference, flat: added light per pixel (frame minus the frame without caustics), top
// row first, width * height each; mask: 1 where the traced frame is lit under the water.
PatternComparison comparePatterns(const std::vector<double>& method,
                                  const std::vector<double>& reference,
                                  const std::vector<double>& flat,
                                  const std::vector<std::uint8_t>& mask, int width, int height);

// The spectrum comparison alone, over `compared` pixels of two patterns (exposed for tests).
PatternSpectrum comparePatternSpectra(const std::vector<double>& method,
                                      const std::vector<double>& reference,
                                      const std::vector<std::uint8_t>& compared, int width,
                                      int height);

}  // namespace ocean::reference
