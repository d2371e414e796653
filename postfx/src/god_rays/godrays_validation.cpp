// Range checks of the god rays' settings.
#include "god_rays/godrays_validation.h"

#include <string>
#include <utility>

namespace postfx::detail {

Result validateGodRays(const GodRaySettings& g, std::string& error) {
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  auto outside = [&fail](const char* field, const auto& value, auto range, const char* unit) {
    return fail(std::string("godRays.") + field + mustBeIn(value, range, unit));
  };
  if (!kGodRaySampleCountRange.contains(g.sampleCount))
    return fail("godRays.sampleCount must be in " + rangeText(kGodRaySampleCountRange) + ", got " +
                std::to_string(g.sampleCount));
  if (!within(g.gridSpacing, kGridSpacingRange))
    return outside("gridSpacing", g.gridSpacing, kGridSpacingRange, " m");
  if (!within(g.intensity, kIntensityRange))
    return outside("intensity", g.intensity, kIntensityRange, "");
  if (!within(g.surfaceFadeDistance, kFadeDepthRange))
    return outside("surfaceFadeDistance", g.surfaceFadeDistance, kFadeDepthRange, " m");
  if (!within(g.depthFadeDistance, kDepthFadeDistanceRange))
    return outside("depthFadeDistance", g.depthFadeDistance, kDepthFadeDistanceRange, " m");
  if (!within(g.maxDistance, kMaxMarchDistanceRange))
    return outside("maxDistance", g.maxDistance, kMaxMarchDistanceRange, " m");
  if (g.resolution != GodRayResolution::Full && g.resolution != GodRayResolution::Half &&
      g.resolution != GodRayResolution::Quarter)
    return fail(notAnEnum("godRays.resolution", static_cast<long long>(g.resolution),
                          "GodRayResolution", "Full = 1, Half = 2 or Quarter = 4"));
  return Result::Ok;
}

}  // namespace postfx::detail
