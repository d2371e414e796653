#include "object_caustics/object_caustics_light_validation.h"

#include <cmath>

#include "core/validation.h"
#include "object_caustics/object_caustics_validation.h"

namespace postfx::detail {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

Result checkLight(int index, const LocalLight& light, std::string& error) {
  const std::string field = "objectCaustics.lights[" + std::to_string(index) + "]";
  auto fail = [&](const std::string& message) {
    error = field + message;
    return Result::InvalidArgument;
  };
  if (light.type != LocalLightType::Point && light.type != LocalLightType::Spot)
    return fail(".type " + std::to_string(static_cast<std::uint32_t>(light.type)) +
                " is not a LocalLightType (Point or Spot)");
  if (!finite(light.position)) return fail(".position is not finite (NaN or Inf)");
  for (int a = 0; a < 3; ++a)
    if (!(std::abs(light.position[a]) <= kMaxWorldCoordinate))
      return fail(".position must lie within +-" + worldExtentText() + " m of the origin");
  if (!within(light.intensity, kLightIntensityRange))
    return fail(".intensity" + mustBeIn(light.intensity, kLightIntensityRange, " per channel"));
  if (!within(light.range, kLightRangeRange))
    return fail(".range" + mustBeIn(light.range, kLightRangeRange, " m, got ") +
                number(light.range));
  if (light.type == LocalLightType::Spot) {
    // The squared length must be finite too: the normalisation divides by its root.
    const glm::dvec3& d = light.direction;
    const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    if (!finite(d) || !within(length, kSunLengthRange))
      return fail(".direction's length must be in " + rangeText(kSunLengthRange) + ", got " +
                  number(length));
    const float angle = light.coneAngleDegrees;
    if (!(angle > kSpotConeAngleRange.min && angle < kSpotConeAngleRange.max))
      return fail(".coneAngleDegrees must be in the open interval (" +
                  number(kSpotConeAngleRange.min) + ", " + number(kSpotConeAngleRange.max) +
                  ") degrees, got " + number(angle));
    if (!within(light.coneSoftness, kSpotConeSoftnessRange))
      return fail(".coneSoftness" + mustBeIn(light.coneSoftness, kSpotConeSoftnessRange, ", got ") +
                  number(light.coneSoftness));
  }
  return checkReceivers(field + ".receivers", light.receivers, error);
}

}  // namespace

Result validateLocalLights(const CreateDesc& create, const ObjectCausticsFrame& frame,
                           std::string& error) {
  if (frame.lightCount < 0 || frame.lightCount > create.maxLocalLights) {
    error = "objectCaustics.lightCount must be in [0, " + std::to_string(create.maxLocalLights) +
            "] (CreateDesc.maxLocalLights), got " + std::to_string(frame.lightCount);
    return Result::InvalidArgument;
  }
  if (frame.lightCount == 0) return Result::Ok;
  if (frame.lights == nullptr) {
    error = "objectCaustics.lights is null but lightCount > 0";
    return Result::InvalidArgument;
  }
  for (int i = 0; i < frame.lightCount; ++i) {
    const Result r = checkLight(i, frame.lights[i], error);
    if (r != Result::Ok) return r;
  }
  return Result::Ok;
}

}  // namespace postfx::detail
