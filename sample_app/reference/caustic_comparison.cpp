#include "caustic_comparison.h"

#include <algorithm>
#include <cmath>

namespace ocean::reference {

CausticComparison compareAddedLight(const std::vector<double>& method,
                                    const std::vector<double>& reference,
                                    const std::vector<std::uint8_t>& mask) {
  CausticComparison c;
  const size_t n = std::min({method.size(), reference.size(), mask.size()});
  double sumM = 0.0, sumR = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!mask[i]) continue;
    sumM += method[i];
    sumR += reference[i];
    ++c.pixels;
  }
  if (c.pixels == 0) return c;
  c.methodMean = sumM / static_cast<double>(c.pixels);
  c.referenceMean = sumR / static_cast<double>(c.pixels);
  // Two passes about the means: no cancellation of large sums.
  double error2 = 0.0, reference2 = 0.0, covariance = 0.0, varianceM = 0.0, varianceR = 0.0;
  for (size_t i = 0; i < n; ++i) {
    if (!mask[i]) continue;
    const double e = method[i] - reference[i];
    error2 += e * e;
    reference2 += reference[i] * reference[i];
    const double dm = method[i] - c.methodMean, dr = reference[i] - c.referenceMean;
    covariance += dm * dr;
    varianceM += dm * dm;
    varianceR += dr * dr;
  }
  c.relativeRmse = reference2 > 0.0 ? std::sqrt(error2 / reference2) : 0.0;
  c.correlation =
      varianceM > 0.0 && varianceR > 0.0 ? covariance / std::sqrt(varianceM * varianceR) : 0.0;
  c.methodStd = std::sqrt(varianceM / static_cast<double>(c.pixels));
  c.referenceStd = std::sqrt(varianceR / static_cast<double>(c.pixels));
  return c;
}

}  // namespace ocean::reference
