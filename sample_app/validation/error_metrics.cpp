#include "error_metrics.h"

#include <algorithm>
#include <cmath>

namespace ocean::validation {

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

double affineRmseDifferenceNoise(const std::vector<double>& a, const ErrorStats& statsA,
                                 const std::vector<double>& b, const ErrorStats& statsB,
                                 const std::vector<double>& reference,
                                 const std::vector<double>& sigma) {
  const size_t n = std::min({a.size(), b.size(), reference.size(), sigma.size()});
  double rr = 0.0, resA = 0.0, resB = 0.0;
  auto residual = [&](const std::vector<double>& x, const ErrorStats& s, size_t i) {
    return reference[i] - (s.fitScale * x[i] + s.fitOffset);
  };
  for (size_t i = 0; i < n; ++i) {
    rr += reference[i] * reference[i];
    resA += residual(a, statsA, i) * residual(a, statsA, i);
    resB += residual(b, statsB, i) * residual(b, statsB, i);
  }
  if (!(rr > 0.0) || !(resA > 0.0) || !(resB > 0.0)) return 0.0;
  const double norm = std::sqrt(rr), normA = std::sqrt(resA), normB = std::sqrt(resB);
  double variance = 0.0;
  for (size_t i = 0; i < n; ++i) {
    const double gradA =
        residual(a, statsA, i) / (normA * norm) - statsA.affineRmse * reference[i] / rr;
    const double gradB =
        residual(b, statsB, i) / (normB * norm) - statsB.affineRmse * reference[i] / rr;
    variance += (gradB - gradA) * (gradB - gradA) * sigma[i] * sigma[i];
  }
  return std::sqrt(variance);
}

}  // namespace ocean::validation
