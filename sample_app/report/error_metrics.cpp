#include "error_metrics.h"

#include <algorithm>
#include <cmath>

namespace ocean::report {

ErrorStats compareWithReference(const std::vector<double>& value,
                                const std::vector<double>& reference,
                                const std::vector<bool>& mask) {
  ErrorStats stats;
  double sx = 0.0, sr = 0.0, sxx = 0.0, srr = 0.0, sxr = 0.0, error = 0.0;
  bool broken = false;
  for (size_t i = 0; i < value.size() && i < reference.size(); ++i) {
    if (!mask.empty() && !mask[i]) continue;
    const double x = value[i], r = reference[i];
    if (!std::isfinite(x)) broken = true;
    if (!std::isfinite(x) || !std::isfinite(r)) continue;
    ++stats.count;
    sx += x, sr += r, sxx += x * x, srr += r * r, sxr += x * r;
    error += (x - r) * (x - r);
  }
  if (stats.count == 0 || !(srr > 0.0)) return stats;
  const double n = double(stats.count);
  stats.relativeRmse = broken ? HUGE_VAL : std::sqrt(error / srr);
  const double varX = sxx - sx * sx / n, varR = srr - sr * sr / n, cov = sxr - sx * sr / n;
  stats.fitScale = varX > 0.0 ? cov / varX : 0.0;
  stats.fitOffset = (sr - stats.fitScale * sx) / n;
  // Residual of the least-squares fit: varR - cov^2 / varX (clamped against rounding).
  const double residual = varX > 0.0 ? std::max(varR - cov * cov / varX, 0.0) : varR;
  stats.affineRmse = broken ? HUGE_VAL : std::sqrt(residual / srr);
  stats.correlation = varX > 0.0 && varR > 0.0 ? cov / std::sqrt(varX * varR) : 0.0;
  return stats;
}

}  // namespace ocean::report
