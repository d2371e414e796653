#pragma once
// How far a pass's output is from its reference, over the pixels both define.
#include <vector>

namespace ocean::report {

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

}  // namespace ocean::report
