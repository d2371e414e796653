#include "reflected_caustics/reflected_validation.h"

#include <utility>

#include "core/validation.h"

namespace postfx::detail {

Result validateReflectedCaustics(const ReflectedCausticsSettings& s, std::string& error) {
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  auto outside = [&fail](const char* field, auto range, const char* unit) {
    return fail(std::string("reflectedCaustics.") + field + " must be in " + rangeText(range) +
                unit);
  };
  auto outsideInt = [&fail](const char* field, Range<int> range, int value) {
    return fail(std::string("reflectedCaustics.") + field + " must be in " + rangeText(range) +
                ", got " + std::to_string(value));
  };
  if (!within(s.intensity, kIntensityRange)) return outside("intensity", kIntensityRange, "");
  if (!within(s.windowSize, kWindowSizeRange)) return outside("windowSize", kWindowSizeRange, " m");
  if (!kReflectedGridRange.contains(s.gridResolution))
    return outsideInt("gridResolution", kReflectedGridRange, s.gridResolution);
  if (!kReflectedLayersRange.contains(s.heightLayers))
    return outsideInt("heightLayers", kReflectedLayersRange, s.heightLayers);
  if (!within(s.maxHeight, kReflectedHeightRange))
    return outside("maxHeight", kReflectedHeightRange, " m");
  if (!within(s.maxIrradiance, kMaxIrradianceRange))
    return outside("maxIrradiance", kMaxIrradianceRange, "");
  return Result::Ok;
}

}  // namespace postfx::detail
