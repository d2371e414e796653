// Checks of the local water regions, before any GL work: a region refused names its index and
// field, and the frame draws nothing.
#include "seabed_caustics/local_water_validation.h"

#include <cmath>
#include <string>
#include <utility>

namespace postfx::detail {
namespace {

std::string regionField(int i, const char* field) {
  return "water.localWater[" + std::to_string(i) + "]." + field;
}

}  // namespace

Result validateLocalWaterValues(const CreateDesc& create, const WaterSurface& water,
                                std::string& error) {
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  if (water.localWaterCount == 0) return Result::Ok;
  if (water.localWaterCount < 0 || water.localWaterCount > kMaxLocalWater)
    return fail("water.localWaterCount must be in [0, " + std::to_string(kMaxLocalWater) +
                "], got " + std::to_string(water.localWaterCount));
  if (!hasFeature(create.features, Feature::LocalWater))
    return fail("water.localWaterCount " + std::to_string(water.localWaterCount) +
                ": local water needs Feature::LocalWater at create()");
  if (water.localWater == nullptr)
    return fail("water.localWater is null but localWaterCount is " +
                std::to_string(water.localWaterCount));
  for (int i = 0; i < water.localWaterCount; ++i) {
    const LocalWater& r = water.localWater[i];
    if (!std::isfinite(r.centre.x) || !std::isfinite(r.centre.y) ||
        !(std::abs(r.centre.x) <= kMaxWorldCoordinate) ||
        !(std::abs(r.centre.y) <= kMaxWorldCoordinate))
      return fail(regionField(i, "centre") + " must be finite and within +-" + worldExtentText() +
                  " m");
    if (!within(r.size.x, kLocalWaterSizeRange) || !within(r.size.y, kLocalWaterSizeRange))
      return fail(regionField(i, "size") + " must be in " + rangeText(kLocalWaterSizeRange) +
                  " m on each side, got (" + number(r.size.x) + ", " + number(r.size.y) + ")");
    if (!within(r.rotation, kLocalWaterRotationRange))
      return fail(regionField(i, "rotation") +
                  mustBeIn(r.rotation, kLocalWaterRotationRange, " radians"));
    if (r.mode != LocalWaterMode::Add && r.mode != LocalWaterMode::Replace)
      return fail(notAnEnum(regionField(i, "mode"), static_cast<long long>(r.mode),
                            "LocalWaterMode", "Add or Replace"));
    const double halfShorter = 0.5 * std::min(r.size.x, r.size.y);
    if (!(r.edgeBlend >= 0.0f) || !(double(r.edgeBlend) <= halfShorter))
      return fail(regionField(i, "edgeBlend") + " must be in [0, " + number(halfShorter) +
                  "] m (half the shorter side)");
    if (!kLocalWaterGridRange.contains(r.gridResolution))
      return fail(regionField(i, "gridResolution") + " must be in " +
                  rangeText(kLocalWaterGridRange) + ", got " + std::to_string(r.gridResolution));
    if (!kLocalWaterLayerRange.contains(r.depthLayers))
      return fail(regionField(i, "depthLayers") + " must be in " +
                  rangeText(kLocalWaterLayerRange) + ", got " + std::to_string(r.depthLayers));
    if (!within(r.maxDepth, kLocalWaterDepthRange))
      return fail(regionField(i, "maxDepth") + mustBeIn(r.maxDepth, kLocalWaterDepthRange, " m"));
  }
  return Result::Ok;
}

Result validateLocalWaterTextures(const WaterSurface& water, std::string& error) {
  for (int i = 0; i < water.localWaterCount; ++i) {
    const std::string field = regionField(i, "texture");
    TextureFacts facts;
    const Result r = checkTexture(field.c_str(), water.localWater[i].texture, {GL_TEXTURE_2D},
                                  {GL_RGBA16F, GL_RGBA32F, GL_RG16F, GL_RG32F}, facts, error);
    if (r != Result::Ok) return r;
  }
  return Result::Ok;
}

}  // namespace postfx::detail
