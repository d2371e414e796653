// Range checks of the seabed caustics' settings, every model's (a frame may switch models).
#include "seabed_caustics/caustics_validation.h"

#include <string>
#include <utility>

namespace postfx::detail {

Result validateCausticsSettings(const CreateDesc& create, const CausticsSettings& s,
                                std::string& error) {
  auto fail = [&error](std::string message) {
    error = std::move(message);
    return Result::InvalidArgument;
  };
  auto outside = [&fail](const char* field, const auto& value, auto range, const char* unit) {
    return fail(std::string("caustics.") + field + mustBeIn(value, range, unit));
  };
  if (!within(s.tau, kTauRange)) return outside("tau", s.tau, kTauRange, "");
  if (!within(s.reflectionWeight, kUnitRange))
    return outside("reflectionWeight", s.reflectionWeight, kUnitRange, "");
  if (!within(s.intensity, kIntensityRange))
    return outside("intensity", s.intensity, kIntensityRange, "");
  if (!within(s.surfaceFadeDepth, kFadeDepthRange))
    return outside("surfaceFadeDepth", s.surfaceFadeDepth, kFadeDepthRange, " m");
  if (!within(s.triplanarSharpness, kTriplanarSharpnessRange))
    return outside("triplanarSharpness", s.triplanarSharpness, kTriplanarSharpnessRange, "");
  if (!within(s.lodBias, kLodBiasRange)) return outside("lodBias", s.lodBias, kLodBiasRange, "");
  if (!within(s.minCascadeContrast, kUnitRange))
    return outside("minCascadeContrast", s.minCascadeContrast, kUnitRange, "");
  if (s.model != CausticsModel::RayDeviation && s.model != CausticsModel::WavefrontAreaRatio &&
      s.model != CausticsModel::TileIrradiance)
    return fail(notAnEnum("caustics.model", static_cast<long long>(s.model), "CausticsModel",
                          "RayDeviation, WavefrontAreaRatio or TileIrradiance"));
  const bool powerOfTwo = s.tileResolution > 0 && (s.tileResolution & (s.tileResolution - 1)) == 0;
  if (!kTileResolutionRange.contains(s.tileResolution) || !powerOfTwo)
    return fail("caustics.tileResolution must be a power of two in " +
                rangeText(kTileResolutionRange) + ", got " + std::to_string(s.tileResolution));
  if (!within(s.tileMinModulation, kTileMinModulationRange))
    return outside("tileMinModulation", s.tileMinModulation, kTileMinModulationRange, "");
  if (s.tileLookupResolution != CausticsLookupResolution::Full &&
      s.tileLookupResolution != CausticsLookupResolution::Half)
    return fail(notAnEnum("caustics.tileLookupResolution",
                          static_cast<long long>(s.tileLookupResolution),
                          "CausticsLookupResolution", "Full = 1 or Half = 2"));
  if (s.tilePointsPerTexel != 1 && s.tilePointsPerTexel != 2)
    return fail("caustics.tilePointsPerTexel must be 1 or 2, got " +
                std::to_string(s.tilePointsPerTexel));
  if (s.tileDepthLayers != 4 && s.tileDepthLayers != 8)
    return fail("caustics.tileDepthLayers must be 4 or 8, got " +
                std::to_string(s.tileDepthLayers));
  if (s.model == CausticsModel::WavefrontAreaRatio &&
      !hasFeature(create.features, Feature::WavefrontAreaRatio))
    return fail("caustics.model WavefrontAreaRatio needs Feature::WavefrontAreaRatio at create()");
  if (!kGridResolutionRange.contains(s.gridResolution))
    return fail("caustics.gridResolution must be in " + rangeText(kGridResolutionRange) + ", got " +
                std::to_string(s.gridResolution));
  if (!within(s.windowSize, kWindowSizeRange))
    return outside("windowSize", s.windowSize, kWindowSizeRange, " m");
  if (!kDepthLayersRange.contains(s.depthLayers))
    return fail("caustics.depthLayers must be in " + rangeText(kDepthLayersRange) + ", got " +
                std::to_string(s.depthLayers));
  if (!within(s.maxReceiverDepth, kMaxReceiverDepthRange))
    return outside("maxReceiverDepth", s.maxReceiverDepth, kMaxReceiverDepthRange, " m");
  if (!within(s.maxIrradiance, kMaxIrradianceRange))
    return outside("maxIrradiance", s.maxIrradiance, kMaxIrradianceRange, "");
  return Result::Ok;
}

}  // namespace postfx::detail
