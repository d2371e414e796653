#include "core/frame_plan.h"

#include <postfx/testing.h>

#include "core/context.h"
#include "core/visibility.h"
#include "object_caustics/object_caustics_frame.h"
#include "object_caustics/object_caustics_light_frame.h"
#include "reflected_caustics/reflected_caustics_pass.h"
#include "seabed_caustics/caustics_constants.h"

namespace postfx::detail {
namespace {

// Sun above the horizon and some of the view frustum under the water: the common condition of
// both lighting passes.
bool underwaterLit(const Context& context, const FrameDesc& frame) {
  if (!(frame.sun.direction.y > 0.0)) return false;  // at or below the horizon
  return frustumReachesBelowWater(viewToWorldRotation(frame.camera.view), frame.camera.projection,
                                  context.desc.depthConvention,
                                  frame.water.level - frame.camera.position.y);
}

bool causticsHaveWork(const Context& context, const FrameDesc& frame) {
  return hasFeature(context.desc.features, Feature::Caustics) && frame.caustics.enabled &&
         underwaterLit(context, frame);
}

bool godRaysHaveWork(const Context& context, const FrameDesc& frame) {
  return hasFeature(context.desc.features, Feature::GodRays) && frame.godRays.enabled &&
         frame.godRays.intensity > 0.0f && underwaterLit(context, frame);
}

// The sun's caustics wanted, casters given, sun above the horizon and some caster inside the
// receiver map's view: else nothing can land anywhere.
bool objectCausticsHaveWork(const Context& context, const FrameDesc& frame) {
  const ObjectCausticsFrame& o = frame.objectCaustics;
  return hasFeature(context.desc.features, Feature::ObjectCaustics) && o.settings.enabled &&
         o.sunCaustics && o.casterCount > 0 && o.settings.intensity > 0.0f &&
         frame.sun.direction.y > 0.0 && castersInReceiverView(o);
}

}  // namespace

bool FramePlan::runs(Pass pass) const {
  switch (pass) {
    case Pass::WavefrontAreaRatio:
      return wavefrontAreaRatio;
    case Pass::TileIrradiance:
      return tile;
    case Pass::Floor:
      return floor && fullScreen;
    case Pass::Caustics:
      return caustics;
    case Pass::GodRays:
      return godRays;
    case Pass::ObjectCaustics:
      return objects;
    case Pass::LocalWater:
      return localWater;
    case Pass::ReflectedCaustics:
      return reflected;
  }
  return false;
}

FramePlan planFrame(const Context& context, const FrameDesc& frame) {
  FramePlan plan;
  plan.caustics = causticsHaveWork(context, frame);
  plan.godRays = godRaysHaveWork(context, frame);
  // The model's light field serves the seabed caustics and the god rays (whose shafts take their
  // light from it): computed when either draws, left out when neither does.
  const bool fieldNeeded = plan.caustics || plan.godRays;
  plan.wavefrontAreaRatio = fieldNeeded && wavefrontAreaRatioActive(context.desc, frame);
  plan.tile = fieldNeeded && tileIrradianceActive(frame);
  plan.localWater = fieldNeeded && hasFeature(context.desc.features, Feature::LocalWater) &&
                    frame.water.localWaterCount > 0;
  plan.reflected = reflectedCausticsHaveWork(context.desc, frame);
  plan.objects = objectCausticsHaveWork(context, frame);
  if (hasFeature(context.desc.features, Feature::ObjectCaustics)) {
    for (int i = 0; i < context.desc.maxLocalLights; ++i) {
      ObjectLightFrame view;
      plan.lightSkip[i] = fitLocalLightFrame(frame, i, view);
      if (plan.lightSkip[i] == LightSkip::None) plan.lights[plan.lightCount++] = i;
    }
  }
  plan.floor = hasFeature(context.desc.features, testing::BenchmarkFloor);
  plan.fullScreen =
      plan.caustics || plan.godRays || plan.reflected || (plan.objectMaps() && plan.floor);
  return plan;
}

}  // namespace postfx::detail
