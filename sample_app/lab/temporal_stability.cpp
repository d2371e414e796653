#include "temporal_stability.h"

#include <algorithm>
#include <cmath>

namespace ocean {
namespace {

// Light below 1e-30 (of a sun of ~1) reads as 0. Where the water absorbs almost everything,
// the shaders' intermediate values become subnormal, and llvmpipe's threads do not all flush
// those alike: the same frame held 2.69876e-37 in one run and 2.6989e-37 in the next
// (measured: the object caustics' farthest light). No display shows such light; a still frame
// must still change by exactly nothing above it.
double visible(float v) {
  return std::abs(v) < 1e-30f ? 0.0 : double(v);
}

double luminance(const glm::vec4& c) {
  return 0.2126 * visible(c.r) + 0.7152 * visible(c.g) + 0.0722 * visible(c.b);
}

}  // namespace

AddedLightChange addedLightChange(const std::vector<std::vector<glm::vec4>>& frames) {
  AddedLightChange out;
  if (frames.size() < 2) return out;
  const size_t pixels = frames.front().size();
  for (const auto& frame : frames)
    if (frame.size() != pixels || pixels == 0) return out;
  out.pairs = int(frames.size() - 1);
  // Pixels dark in both frames of a pair add nothing to either sum: leaving them out changes
  // no ratio of sums, and keeps the percentile on the light.
  std::vector<double> changes;
  changes.reserve(pixels * (frames.size() - 1));
  double change = 0.0, light = 0.0;
  for (size_t k = 0; k + 1 < frames.size(); ++k) {
    for (size_t i = 0; i < pixels; ++i) {
      const double a = luminance(frames[k][i]), b = luminance(frames[k + 1][i]);
      if (!std::isfinite(a) || !std::isfinite(b) || !(a > 0.0 || b > 0.0)) continue;
      changes.push_back(std::abs(b - a));
      change += std::abs(b - a);
      light += 0.5 * (a + b);
    }
  }
  if (changes.empty() || !(light > 0.0)) return out;
  out.meanLight = light / double(changes.size());
  out.mean = change / light;
  const size_t k = (changes.size() - 1) * 99 / 100;
  std::nth_element(changes.begin(), changes.begin() + long(k), changes.end());
  out.p99 = changes[k] / out.meanLight;
  return out;
}

}  // namespace ocean
