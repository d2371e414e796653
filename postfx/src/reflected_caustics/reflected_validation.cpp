#include "reflected_caustics/reflected_validation.h"

#include <utility>

#include "core/validation.h"

namespace postfx::detail {

Result validateReflectedCaustics(const ReflectedCausticsSettings& s, std::string& error) {
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  auto outside = [&fail](const char* field, const auto& value, auto range, const char* unit) {
    return fail(std::string("reflectedCaustics.") + field + mustBeIn(value, range, unit));
  };
  auto outsideInt = [&fail](const char* field, Range<int> range, int value) {
    return fail(std::string("reflectedCaustics.") + field + " must be in " + rangeText(range) +
                ", got " + std::to_string(value));
  };
  if (s.landing != ReflectedLanding::ViewDepth && s.landing != ReflectedLanding::HeightLayers)
    return fail(notAnEnum("reflectedCaustics.landing", static_cast<long long>(s.landing),
                          "ReflectedLanding", "ViewDepth or HeightLayers"));
  if (!within(s.intensity, kIntensityRange))
    return outside("intensity", s.intensity, kIntensityRange, "");
  if (!within(s.windowSize, kWindowSizeRange))
    return outside("windowSize", s.windowSize, kWindowSizeRange, " m");
  if (!kReflectedGridRange.contains(s.gridResolution))
    return outsideInt("gridResolution", kReflectedGridRange, s.gridResolution);
  if (!kReflectedLayersRange.contains(s.heightLayers))
    return outsideInt("heightLayers", kReflectedLayersRange, s.heightLayers);
  if (!within(s.maxHeight, kReflectedHeightRange))
    return outside("maxHeight", s.maxHeight, kReflectedHeightRange, " m");
  if (!within(s.maxIrradiance, kMaxIrradianceRange))
    return outside("maxIrradiance", s.maxIrradiance, kMaxIrradianceRange, "");
  return Result::Ok;
}

}  // namespace postfx::detail
