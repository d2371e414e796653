#include "core/memory_estimate.h"

#include <postfx/testing.h>

#include "god_rays/godrays_constants.h"
#include "seabed_caustics/tile_irradiance_pass.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {
namespace {

std::uint64_t square(int side) {
  return static_cast<std::uint64_t>(side) * static_cast<std::uint64_t>(side);
}

// Each term with the field that sets it, for the message.
struct Terms {
  std::uint64_t raw = 0, godRays = 0, irradiance = 0, tile = 0, casterMaps = 0, causticMap = 0;
};

Terms terms(const CreateDesc& create, const FrameDesc& frame, int width, int height,
            const FramePlan& passes) {
  Terms t;
  const std::uint64_t pixels = static_cast<std::uint64_t>(width) * std::uint64_t(height);
  if (hasFeature(create.features, testing::RawCausticOutput)) t.raw = pixels * 2;  // R16F
  if (passes.godRays && frame.godRays.resolution != GodRayResolution::Full)
    t.godRays = static_cast<std::uint64_t>(godRayReducedSize(width, frame.godRays.resolution)) *
                std::uint64_t(godRayReducedSize(height, frame.godRays.resolution)) *
                8;  // RG32UI: four halves
  // Exactly what the passes allocate (their allocatedBytes() asks GL; a test compares). The
  // tile irradiance also runs in WavefrontAreaRatio frames: it continues the window.
  if (passes.wavefrontAreaRatio)
    t.irradiance = wavefrontAreaRatioBytes(frame.caustics.gridResolution,
                                           frame.caustics.depthLayers, landingSpreadOn(frame));
  if (passes.tile) {
    t.tile = tileIrradianceBytes(tileIrradianceLayout(frame));
    // The half-resolution lookups (the TileIrradiance model's only): RG16F, irradiance and
    // distance.
    if (passes.caustics && frame.caustics.model == CausticsModel::TileIrradiance &&
        frame.caustics.tileLookupResolution == CausticsLookupResolution::Half)
      t.tile += std::uint64_t((width + 1) / 2) * std::uint64_t((height + 1) / 2) * 4;
  }
  if (passes.objectMaps()) {
    const ObjectCausticsSettings& s = frame.objectCaustics.settings;
    // Front/back positions RGBA32F, normals RGBA16F, one D32F depth; where each ray lands and
    // its flux, RGBA32F, per colour channel when dispersion may split them.
    const std::uint64_t channels = hasFeature(create.features, Feature::Dispersion) ? 3 : 1;
    t.casterMaps = square(s.gridSize) * (16 + 8 + 16 + 8 + 4 + channels * 2 * 16);
    // The sun's splats and two temporal histories, and one map all the local lights share,
    // RGBA32F.
    t.causticMap =
        square(s.mapSize) * 16 * ((passes.objects ? 3 : 0) + (passes.lightCount > 0 ? 1 : 0));
  }
  return t;
}

std::string mib(std::uint64_t bytes) {
  return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB";
}

}  // namespace

std::uint64_t frameMemoryBytes(const CreateDesc& create, const FrameDesc& frame, int width,
                               int height, const FramePlan& passes) {
  const Terms t = terms(create, frame, width, height, passes);
  return t.raw + t.godRays + t.irradiance + t.tile + t.casterMaps + t.causticMap;
}

Result checkFrameMemory(const CreateDesc& create, const FrameDesc& frame, int width, int height,
                        const FramePlan& passes, std::string& error) {
  const Terms t = terms(create, frame, width, height, passes);
  const std::uint64_t total =
      t.raw + t.godRays + t.irradiance + t.tile + t.casterMaps + t.causticMap;
  const std::uint64_t budget = static_cast<std::uint64_t>(create.memoryBudgetMiB) << 20;
  if (total <= budget) return Result::Ok;
  const char* largest = "the raw caustic output (target size)";
  std::uint64_t most = t.raw;
  const std::pair<std::uint64_t, const char*> others[] = {
      {t.godRays, "the god-ray march texture (target size, godRays.resolution)"},
      {t.irradiance, "the irradiance layers (caustics.gridResolution, depthLayers)"},
      {t.tile,
       "the tile irradiance (caustics.tileResolution, tileDepthLayers, tileLookupResolution)"},
      {t.casterMaps, "the caster maps (objectCaustics.settings.gridSize)"},
      {t.causticMap, "the caustic map and its history (objectCaustics.settings.mapSize)"}};
  for (const auto& [bytes, name] : others)
    if (bytes > most) {
      most = bytes;
      largest = name;
    }
  error = "frame needs " + mib(total) + " of GPU memory, over CreateDesc.memoryBudgetMiB = " +
          std::to_string(create.memoryBudgetMiB) + " MiB; most of it (" + mib(most) + ") for " +
          largest;
  return Result::OutOfMemory;
}

}  // namespace postfx::detail
