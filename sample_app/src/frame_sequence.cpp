#include "frame_sequence.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "view_flags.h"

namespace ocean {

std::string sequenceFrameName(const std::string& path, int frame, int frames) {
  const std::filesystem::path p(path);
  int digits = 4;
  for (int n = frames - 1; n >= 10000; n /= 10) ++digits;
  char number[16];
  std::snprintf(number, sizeof number, "_%0*d", digits, frame);
  return (p.parent_path() / (p.stem().string() + number + p.extension().string())).string();
}

bool cameraAt(const Options& options, const Camera& first, double seconds, Camera& camera) {
  camera = first;
  if (!options.cameraVelocity) return true;
  camera.position = first.position + *options.cameraVelocity * seconds;
  // The same bound as --camera-position's: a fast path over a long sequence must not leave it.
  if (!(glm::length(camera.position) <= 1e7)) return false;
  if (!options.cameraLookAt) return true;
  return lookAlong(*options.cameraLookAt - camera.position, camera.yaw, camera.pitch);
}

double relativeFrameChange(const std::vector<float>& a, const std::vector<float>& b) {
  if (a.size() != b.size() || a.empty()) return 0.0;
  // Rec. 709 luminance: the change a viewer sees, not the change of one channel.
  auto luminance = [](const std::vector<float>& image, size_t i) {
    return 0.2126 * double(image[i]) + 0.7152 * double(image[i + 1]) +
           0.0722 * double(image[i + 2]);
  };
  double change = 0.0, level = 0.0;
  for (size_t i = 0; i + 3 < a.size(); i += 4) {
    const double la = luminance(a, i), lb = luminance(b, i);
    if (!std::isfinite(la) || !std::isfinite(lb)) continue;
    change += std::abs(lb - la);
    level += std::abs(la);
  }
  return level > 0.0 ? change / level : 0.0;
}

}  // namespace ocean
