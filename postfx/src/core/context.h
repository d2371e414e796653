#pragma once
// What a postfx::Context holds: the creation choices, the passes' GL objects (programs and the
// per-frame work every view shares), the shared passes' timers, its views and the last error
// message.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <postfx/testing.h>

#include "core/gpu_timers.h"
#include "core/view_state.h"
#include "god_rays/godrays_constants.h"
#include "god_rays/godrays_pass.h"
#include "object_caustics/object_caustics_pass.h"
#include "reflected_caustics/reflected_caustics_pass.h"
#include "seabed_caustics/caustics_pass.h"
#include "seabed_caustics/local_water_pass.h"
#include "seabed_caustics/tile_irradiance_pass.h"
#include "seabed_caustics/wavefront_area_ratio_pass.h"

namespace postfx {

struct Context {
  CreateDesc desc;
  detail::CausticsPass caustics;
  detail::GodRaysPass godRays;
  testing::GodRaySampling godRaySampling = testing::GodRaySampling::WorldGrid;
  float godRayUniformPhase = 0.5f;
  detail::WavefrontAreaRatioPass wavefrontAreaRatio;  // Feature::WavefrontAreaRatio only
  // Compiled the first time a frame uses the TileIrradiance model.
  detail::TileIrradiancePass tileIrradiance;
  bool tileIrradianceReady = false;
  detail::LocalWaterPass localWater;        // Feature::LocalWater only
  detail::ReflectedCausticsPass reflected;  // Feature::ReflectedCaustics only
  detail::ObjectCausticsPass objectCaustics;
  // The shared passes: Pass::TileIrradiance, LocalWater, ObjectCaustics, the lights.
  detail::GpuTimers timers;
  std::array<bool, kPassCount> present{};    // the passes the context has, for its views' timers
  View defaultView;                          // dispatch(context, frame)'s
  std::vector<std::unique_ptr<View>> views;  // createView()'s, alive
  // stats(context): the shared passes' timings with the default view's, merged when asked.
  mutable FrameStats mergedStats;
  std::vector<WorkStep> mergedSteps;  // workSteps(context): the shared steps, then the view's
  std::string error;
};

}  // namespace postfx
