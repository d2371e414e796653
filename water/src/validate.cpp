#include <cmath>

#include <postfx/water/ocean_desc.h>

namespace postfx::water {
namespace {

// !(x >= lo && x <= hi) is also true for NaN.
bool inRange(double x, double lo, double hi) {
  return x >= lo && x <= hi;
}

Result fail(std::string& error, std::string message) {
  error = std::move(message);
  return Result::InvalidArgument;
}

}  // namespace

Result validateOceanDesc(const OceanDesc& desc, std::string& error) {
  const int n = desc.resolution;
  if (n < 8 || n > kMaxResolution || (n & (n - 1)) != 0) {
    return fail(error, "resolution must be a power of two in [8, 512], got " + std::to_string(n));
  }
  if (desc.cascadeCount < 1 || desc.cascadeCount > kMaxCascades) {
    return fail(error, "cascadeCount must be in [1, 4], got " + std::to_string(desc.cascadeCount));
  }
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const double size = desc.tileSize[c];
    if (!inRange(size, 1e-2, 1e5)) {
      return fail(error, "tileSize[" + std::to_string(c) + "] must be in [0.01, 1e5] m");
    }
    if (c > 0) {
      const double ratio = desc.tileSize[c - 1] / size;
      if (!(ratio > 1.0)) return fail(error, "tileSize must strictly decrease");
      // The band handover needs the finer fundamental below the coarser Nyquist.
      if (!(ratio < n / 2.0)) {
        return fail(error, "tileSize[" + std::to_string(c - 1) + "] / tileSize[" +
                               std::to_string(c) + "] must be below resolution / 2");
      }
    }
  }
  if (!inRange(desc.windSpeed, 0.0, 60.0)) return fail(error, "windSpeed must be in [0, 60] m/s");
  if (!std::isfinite(desc.windDirection)) return fail(error, "windDirection must be finite");
  if (!inRange(desc.fetch, 1e2, 1e7)) return fail(error, "fetch must be in [1e2, 1e7] m");
  if (!inRange(desc.peakEnhancement, 1.0, 20.0)) {
    return fail(error, "peakEnhancement must be in [1, 20]");
  }
  if (!inRange(desc.spreading, 0.0, 200.0)) return fail(error, "spreading must be in [0, 200]");
  if (!inRange(desc.choppiness, 0.0, 4.0)) return fail(error, "choppiness must be in [0, 4]");
  if (!inRange(desc.depth, 0.0, 1e5)) return fail(error, "depth must be in [0, 1e5] m");
  if (!inRange(desc.loopPeriod, 1.0, 1e6)) return fail(error, "loopPeriod must be in [1, 1e6] s");
  return Result::Ok;
}

}  // namespace postfx::water
