#include "temporal_stability.h"

#include <algorithm>
#include <cmath>

namespace ocean {
namespace {

double luminance(const glm::vec4& c) {
  return 0.2126 * double(c.r) + 0.7152 * double(c.g) + 0.0722 * double(c.b);
}

}  // namespace

AddedLightChange addedLightChange(const std::vector<std::vector<glm::vec4>>& frames) {
  AddedLightChange out;
  if (frames.size() < 2) return out;
  const size_t pixels = frames.front().size();
  for (const auto& frame : frames)
    if (frame.size() != pixels || pixels == 0) return out;
  double light = 0.0;
  size_t lightCount = 0;
  for (const auto& frame : frames) {
    for (const glm::vec4& c : frame) {
      const double l = luminance(c);
      if (!std::isfinite(l)) continue;
      light += l;
      ++lightCount;
    }
  }
  if (lightCount == 0 || !(light > 0.0)) return out;
  out.meanLight = light / double(lightCount);
  std::vector<double> changes;
  changes.reserve(pixels * (frames.size() - 1));
  for (size_t k = 0; k + 1 < frames.size(); ++k) {
    for (size_t i = 0; i < pixels; ++i) {
      const double d = luminance(frames[k + 1][i]) - luminance(frames[k][i]);
      if (std::isfinite(d)) changes.push_back(std::abs(d));
    }
  }
  out.pairs = int(frames.size() - 1);
  if (changes.empty()) return out;
  double sum = 0.0;
  for (double d : changes) sum += d;
  out.mean = sum / double(changes.size()) / out.meanLight;
  const size_t k = (changes.size() - 1) * 99 / 100;
  std::nth_element(changes.begin(), changes.begin() + long(k), changes.end());
  out.p99 = changes[k] / out.meanLight;
  return out;
}

}  // namespace ocean
