#pragma once
// What a postfx::Context holds: the creation choices, the passes' GL objects, the timers and
// the last error message.
#include <string>

#include <postfx/postfx.h>

#include "caustics_pass.h"
#include "godrays_constants.h"
#include "godrays_pass.h"
#include "gpu_timers.h"
#include "irradiance_pass.h"
#include "object_caustics_pass.h"
#include "tile_irradiance_pass.h"

namespace postfx {

struct Context {
  enum PassIndex { kCausticsPass = 0, kFloorPass = 1 };

  CreateDesc desc;
  detail::CausticsPass caustics;
  detail::GodRaysPass godRays;
  detail::GodRayGridPivot godRayPivot;
  int godRaysPass = -1;  // timer index of "god_rays" (after the floor when there is one); -1: off
  detail::IrradiancePass irradiance;  // Feature::PhysicalCaustics only
  int irradiancePass = -1;  // timer index of "caustics_irradiance"; -1: no PhysicalCaustics
  // Compiled the first time a frame uses the TileIrradiance model.
  detail::TileIrradiancePass tileIrradiance;
  bool tileIrradianceReady = false;
  int tileIrradiancePass = -1;  // timer index of "caustics_tile_irradiance"; -1: no Caustics
  detail::ObjectCausticsPass objectCaustics;
  int objectCausticsPass = -1;  // timer index of "object_caustics"; -1: feature off
  detail::GpuTimers timers;
  std::string error;
};

}  // namespace postfx
