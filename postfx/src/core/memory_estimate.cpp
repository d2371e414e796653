#include "core/memory_estimate.h"

#include <postfx/testing.h>

#include <algorithm>

#include "god_rays/godrays_constants.h"
#include "object_caustics/object_caustics_frame.h"
#include "reflected_caustics/reflected_layout.h"
#include "seabed_caustics/local_water_layout.h"
#include "seabed_caustics/tile_irradiance_pass.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {
namespace {

std::uint64_t square(int side) {
  return static_cast<std::uint64_t>(side) * static_cast<std::uint64_t>(side);
}

// Each term with the field that sets it, for the message. raw, godRays and lookups are each
// view's own (summed over the views); the others are shared.
struct Terms {
  std::uint64_t raw = 0, godRays = 0, lookups = 0, irradiance = 0, tile = 0, casterMaps = 0,
                causticMap = 0, localWater = 0, reflected = 0;
  std::uint64_t total() const {
    return raw + godRays + lookups + irradiance + tile + casterMaps + causticMap + localWater +
           reflected;
  }
};

void addViewTerms(const CreateDesc& create, const ViewMemory& v, Terms& t) {
  const FrameDesc& frame = *v.frame;
  const FramePlan& passes = *v.plan;
  if (hasFeature(create.features, testing::RawCausticOutput))
    t.raw += std::uint64_t(v.targetWidth) * std::uint64_t(v.targetHeight) * 2;  // R16F
  if (passes.godRays && frame.godRays.resolution != GodRayResolution::Full)
    t.godRays += static_cast<std::uint64_t>(godRayReducedSize(v.width, frame.godRays.resolution)) *
                 std::uint64_t(godRayReducedSize(v.height, frame.godRays.resolution)) *
                 8;  // RG32UI: four halves
  // The half-resolution lookups (the TileIrradiance model's only): irradiance and distance as
  // two halves.
  if (passes.tile && passes.caustics && frame.caustics.model == CausticsModel::TileIrradiance &&
      frame.caustics.tileLookupResolution == CausticsLookupResolution::Half)
    t.lookups += std::uint64_t((v.width + 1) / 2) * std::uint64_t((v.height + 1) / 2) * 4;
}

Terms terms(const CreateDesc& create, std::span<const ViewMemory> views) {
  Terms t;
  bool irradiance = false, tile = false, localWater = false, reflected = false;
  for (const ViewMemory& v : views) {
    addViewTerms(create, v, t);
    irradiance = irradiance || v.plan->wavefrontAreaRatio;
    tile = tile || v.plan->tile;
    localWater = localWater || v.plan->localWater;
    reflected = reflected || v.plan->reflected;
  }
  // Exactly what the passes allocate (their allocatedBytes() asks GL; a test compares). The
  // tile irradiance also runs in WavefrontAreaRatio frames: it continues the window. The
  // window's layers serve each view in turn.
  const FrameDesc& frame = *views[0].frame;
  const FramePlan& passes = *views[0].plan;
  if (irradiance)
    t.irradiance = wavefrontAreaRatioBytes(frame.caustics.gridResolution,
                                           frame.caustics.depthLayers, landingSpreadOn(frame));
  if (tile) t.tile = tileIrradianceBytes(tileIrradianceLayout(frame));
  if (localWater) t.localWater = localWaterBytes(frame);
  // One field, drawn by each view in turn.
  if (reflected && frame.reflectedCaustics.landing == ReflectedLanding::ViewDepth)
    t.reflected =
        reflectedReceiverBytes(frame.reflectedCaustics.gridResolution, views[0].targetWidth,
                               views[0].targetHeight, frame.caustics.tileUnresolvedSpread);
  else if (reflected)
    t.reflected = reflectedFieldBytes(frame.reflectedCaustics.gridResolution,
                                      frame.reflectedCaustics.heightLayers, landingSpreadOn(frame));
  if (passes.objectMaps()) {
    const ObjectCausticsSettings& s = frame.objectCaustics.settings;
    // Front/back positions RGBA32F, normals RGBA16F, one D32F depth; where each ray lands and
    // its flux, RGBA32F, per colour channel when dispersion may split them.
    // With the volume caustics, each ray's segment and power too (three more RGBA32F).
    const std::uint64_t channels = hasFeature(create.features, Feature::Dispersion) ? 3 : 1;
    const bool volume = volumeCausticsOn(create, frame);
    const std::uint64_t layers = volume ? 5 : 2;
    t.casterMaps = square(s.gridSize) * (16 + 8 + 16 + 8 + 4 + channels * layers * 16);
    // The volume caustics' light, summed in RGBA32F at the largest view's size before it is
    // added to the target.
    if (volume) {
      int width = 0, height = 0;
      for (const ViewMemory& v : views)
        width = std::max(width, v.width), height = std::max(height, v.height);
      t.casterMaps += std::uint64_t(width) * std::uint64_t(height) * 16;
    }
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
  const ViewMemory view{&frame, width, height, width, height, &passes};
  return terms(create, {&view, 1}).total();
}

std::uint64_t frameMemoryBytes(const CreateDesc& create, std::span<const ViewMemory> views) {
  return terms(create, views).total();
}

Result checkFrameMemory(const CreateDesc& create, std::span<const ViewMemory> views,
                        std::string& error) {
  const Terms t = terms(create, views);
  const std::uint64_t total = t.total();
  const std::uint64_t budget = static_cast<std::uint64_t>(create.memoryBudgetMiB) << 20;
  if (total <= budget) return Result::Ok;
  const char* largest = "the raw caustic output (target size, per view)";
  std::uint64_t most = t.raw;
  const std::pair<std::uint64_t, const char*> others[] = {
      {t.godRays, "the god-ray march texture (target size, godRays.resolution, per view)"},
      {t.lookups, "the tile irradiance's half-resolution lookups (target size, per view)"},
      {t.irradiance, "the irradiance layers (caustics.gridResolution, depthLayers)"},
      {t.tile,
       "the tile irradiance (caustics.tileResolution, tileDepthLayers, tileLookupResolution)"},
      {t.casterMaps, "the caster maps (objectCaustics.settings.gridSize)"},
      {t.causticMap, "the caustic map and its history (objectCaustics.settings.mapSize)"},
      {t.localWater, "the local water layers (water.localWater's gridResolution, depthLayers)"},
      {t.reflected,
       "the reflected light's layers (reflectedCaustics.gridResolution, heightLayers)"}};
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
