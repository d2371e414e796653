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
  auto outside = [&fail](const char* field, auto range, const char* unit) {
    return fail(std::string("godRays.") + field + " must be in " + rangeText(range) + unit);
  };
  if (!kGodRaySampleCountRange.contains(g.sampleCount))
    return fail("godRays.sampleCount must be in " + rangeText(kGodRaySampleCountRange) + ", got " +
                std::to_string(g.sampleCount));
  if (!within(g.gridSpacing, kGridSpacingRange))
    return outside("gridSpacing", kGridSpacingRange, " m");
  if (!within(g.intensity, kIntensityRange)) return outside("intensity", kIntensityRange, "");
  if (!within(g.surfaceFadeDistance, kFadeDepthRange))
    return outside("surfaceFadeDistance", kFadeDepthRange, " m");
  if (!within(g.depthFadeDistance, kDepthFadeDistanceRange))
    return outside("depthFadeDistance", kDepthFadeDistanceRange, " m");
  if (!within(g.maxDistance, kMaxMarchDistanceRange))
    return outside("maxDistance", kMaxMarchDistanceRange, " m");
  if (g.resolution != GodRayResolution::Full && g.resolution != GodRayResolution::Half &&
      g.resolution != GodRayResolution::Quarter)
    return fail("godRays.resolution is not a GodRayResolution");
  return Result::Ok;
}

}  // namespace postfx::detail
