#pragma once
// How well a method's added caustic light matches the traced reference's, pixel by pixel:
// relative RMSE and Pearson correlation over a mask (the lit underwater pixels).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace ocean::reference {

struct CausticComparison {
  size_t pixels = 0;          // in the mask
  double relativeRmse = 0.0;  // sqrt(sum (m - r)^2 / sum r^2)
  double correlation = 0.0;   // Pearson's r of m and r; 0 when either is constant
  double methodMean = 0.0, referenceMean = 0.0;
  double methodStd = 0.0, referenceStd = 0.0;  // population standard deviations over the mask
};

// `method` and `reference`: the light each adds at every pixel (e.g. the luminance of frame
// minus the frame without caustics); mask: 1 where the pixel counts. Equal sizes.
CausticComparison compareAddedLight(const std::vector<double>& method,
                                    const std::vector<double>& reference,
                                    const std::vector<std::uint8_t>& mask);

}  // namespace ocean::reference
