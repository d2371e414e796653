#pragma once
// What a postfx::Context holds: the creation choices, the passes' GL objects, the timers and
// the last error message.
#include <string>

#include <postfx/postfx.h>
#include <postfx/testing.h>

#include "core/gpu_timers.h"
#include "god_rays/godrays_constants.h"
#include "god_rays/godrays_pass.h"
#include "object_caustics/object_caustics_pass.h"
#include "seabed_caustics/caustics_pass.h"
#include "seabed_caustics/tile_irradiance_pass.h"
#include "seabed_caustics/wavefront_area_ratio_pass.h"

namespace postfx {

struct Context {
  CreateDesc desc;
  detail::CausticsPass caustics;
  detail::GodRaysPass godRays;
  detail::GodRayGridPivot godRayPivot;
  testing::GodRaySampling godRaySampling = testing::GodRaySampling::WorldGrid;
  float godRayUniformPhase = 0.5f;
  detail::WavefrontAreaRatioPass wavefrontAreaRatio;  // Feature::WavefrontAreaRatio only
  // Compiled the first time a frame uses the TileIrradiance model.
  detail::TileIrradiancePass tileIrradiance;
  bool tileIrradianceReady = false;
  detail::ObjectCausticsPass objectCaustics;
  detail::GpuTimers timers;
  std::string error;
};

}  // namespace postfx
