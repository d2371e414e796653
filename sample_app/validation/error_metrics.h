#pragma once
// How far a pass's output is from its reference, over the pixels both define.
#include <vector>

namespace ocean::validation {

struct ErrorStats {
  double relativeRmse = 0.0;  // sqrt(sum (x - r)^2 / sum r^2)
  double affineRmse = 0.0;    // the same for a x + b, (a, b) the least-squares fit to r
  double correlation = 0.0;   // Pearson; 0 when either side is constant
  double fitScale = 0.0, fitOffset = 0.0;
  long long count = 0;
};

// Compares value[i] with reference[i] where mask is empty or mask[i] is true. Non-finite values
// count as a total miss (they are reported, never skipped).
ErrorStats compareWithReference(const std::vector<double>& value,
                                const std::vector<double>& reference,
                                const std::vector<bool>& mask = {});

// Standard deviation of affineRmse(b) - affineRmse(a), both against the same `reference`, that
// independent noise of standard deviation sigma[i] on reference[i] puts into it, to first order.
// Each error is |residual| / |reference| with the residual orthogonal to its fit, so a change dr
// of the reference moves it by (res / |res| / |r| - err r / |r|^2) . dr (the fit's own change is
// second order). The noise terms common to both errors cancel in the difference, which is why
// this is far below the worst case, twice |sigma| / |r|.
double affineRmseDifferenceNoise(const std::vector<double>& a, const ErrorStats& statsA,
                                 const std::vector<double>& b, const ErrorStats& statsB,
                                 const std::vector<double>& reference,
                                 const std::vector<double>& sigma);

}  // namespace ocean::validation
