#pragma once
// Small measurements on read-back images for property tests.
#include <cmath>
#include <cstdint>
#include <vector>

namespace testsupport {

struct RadianceStats {
  size_t nonFinite = 0;
  double mean = 0.0, max = 0.0;
};

// RGBA float pixels: counts NaN/Inf in rgb and gives mean and max of the finite values.
inline RadianceStats radianceStats(const std::vector<float>& rgba) {
  RadianceStats stats;
  size_t finite = 0;
  for (size_t i = 0; i < rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    if (!std::isfinite(rgba[i])) {
      ++stats.nonFinite;
      continue;
    }
    stats.mean += double(rgba[i]);
    stats.max = std::max(stats.max, double(rgba[i]));
    ++finite;
  }
  if (finite > 0) stats.mean /= double(finite);
  return stats;
}

// Standard deviation of 8-bit luminance-ish values (mean of rgb): 0 for a blank image.
inline double byteImageSpread(const std::vector<uint8_t>& rgba) {
  double sum = 0.0, sum2 = 0.0;
  const size_t pixels = rgba.size() / 4;
  for (size_t p = 0; p < pixels; ++p) {
    const double v = (rgba[4 * p] + rgba[4 * p + 1] + rgba[4 * p + 2]) / 3.0;
    sum += v;
    sum2 += v * v;
  }
  const double mean = sum / double(pixels);
  return std::sqrt(std::max(sum2 / double(pixels) - mean * mean, 0.0));
}

}  // namespace testsupport
