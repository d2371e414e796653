// The public entry points: validation first, GL work only once everything is known good, and
// no exception ever crossing the API boundary.
#include <postfx/postfx.h>
#include <postfx/testing.h>

#include <glkit/current_context.h>

#include <array>
#include <memory>
#include <new>

#include "block_check.h"
#include "context.h"
#include "draw_state_guard.h"
#include "frame_constants.h"
#include "gl_state_guard.h"
#include "godrays_constants.h"
#include "memory_estimate.h"
#include "object_caustics_frame.h"
#include "object_caustics_validation.h"
#include "validation.h"
#include "visibility.h"

namespace postfx {
namespace {

thread_local std::string createError;

// Debug groups name the passes in RenderDoc / Nsight captures.
class DebugGroup {
 public:
  explicit DebugGroup(const char* name) {
    glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0x9f5f0, -1, name);
  }
  ~DebugGroup() { glPopDebugGroup(); }
  DebugGroup(const DebugGroup&) = delete;
  DebugGroup& operator=(const DebugGroup&) = delete;
};

// Sun above the horizon and some of the view frustum under the water: the common condition of
// both lighting passes.
bool underwaterLit(const Context& context, const FrameDesc& frame) {
  if (!(frame.sun.direction.y > 0.0)) return false;  // at or below the horizon
  return detail::frustumReachesBelowWater(detail::viewToWorldRotation(frame.camera.view),
                                          frame.camera.projection, context.desc.depthConvention,
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

// Casters given, sun above the horizon and some caster inside the receiver map's view: else
// nothing can land anywhere.
bool objectCausticsHaveWork(const Context& context, const FrameDesc& frame) {
  const ObjectCausticsFrame& o = frame.objectCaustics;
  return hasFeature(context.desc.features, Feature::ObjectCaustics) && o.settings.enabled &&
         o.casterCount > 0 && o.settings.intensity > 0.0f && frame.sun.direction.y > 0.0 &&
         detail::castersInReceiverView(o);
}

// The object caustics, timed as their own pass, after the seabed caustics and god rays.
void drawObjectCaustics(Context& context, const FrameDesc& frame, int width, int height) {
  DebugGroup group("postfx.object_caustics");
  if (hasFeature(context.desc.features, testing::BenchmarkFloor)) glFinish();
  context.timers.begin(Pass::ObjectCaustics);
  context.objectCaustics.draw(frame, width, height);
  context.timers.end(Pass::ObjectCaustics);
}

Result refuse(std::string& error, const char* message) {
  error = message;
  return Result::InvalidArgument;
}

Result dispatchUnchecked(Context& context, const FrameDesc& frame) {
  std::string& error = context.error;
  Result r = detail::validateFrameValues(context.desc, frame, error);
  if (r != Result::Ok) return r;
  detail::ValidatedTextures textures;
  r = detail::validateFrameTextures(context.desc, frame, textures, error);
  if (r != Result::Ok) return r;
  if (hasFeature(context.desc.features, Feature::ObjectCaustics)) {
    r = detail::validateObjectCaustics(frame, error);
    if (r != Result::Ok) return r;
  }
  r = detail::checkHostDrawState(error);
  if (r != Result::Ok) return r;

  const int width = textures.width, height = textures.height;
  const bool caustics = causticsHaveWork(context, frame);
  const bool godRays = godRaysHaveWork(context, frame);
  const bool physical = caustics && detail::physicalCausticsActive(context.desc, frame);
  const bool tile = caustics && detail::tileIrradianceActive(frame);
  int tileVariant = 0;  // the caustics program's TileIrradiance variant; 0: another model
  const bool floor = hasFeature(context.desc.features, testing::BenchmarkFloor);
  const bool objects = objectCausticsHaveWork(context, frame);
  // The floor runs whenever some timed pass does, so that every pass has its ratio.
  const bool fullScreen = caustics || godRays || (objects && floor);

  // Every constant the GPU will see is built and checked before any GL work. The god-ray pivot
  // is the one piece of per-frame state that shapes the image: a copy moves with this frame and
  // is kept only once the frame has been drawn, so a refused frame leaves no trace.
  const shared::CausticsBlock block =
      detail::buildCausticsBlock(context.desc, frame, width, height, textures.water);
  if (fullScreen && !detail::allFinite(block))
    return refuse(error,
                  "frame: a caustics constant overflows the GPU's float (camera.projection, or "
                  "shadow.worldToLightClip about camera.position, has entries too large)");
  detail::GodRayGridPivot pivot = context.godRayPivot;
  shared::GodRaysBlock godBlock{};
  if (godRays) {
    godBlock = detail::buildGodRaysBlock(
        frame, width, height, pivot,
        context.godRaySampling == testing::GodRaySampling::UniformAlongRay);
    if (!detail::allFinite(godBlock))
      return refuse(error, "frame: a god-ray constant overflows the GPU's float");
  }
  detail::ObjectLightFrame light;
  shared::ObjectCausticsBlock objectBlock{};
  if (objects) {
    light = detail::fitObjectLightFrame(frame);
    objectBlock = detail::buildObjectCausticsBlock(context.desc, frame, light, width, height);
    if (!detail::allFinite(objectBlock) || !detail::casterMatricesFinite(frame, light))
      return refuse(error,
                    "frame: an object-caustics constant overflows the GPU's float "
                    "(objectCaustics.receivers.worldToLightClip or a caster's modelToWorld has "
                    "entries too large)");
  }
  r = detail::checkFrameMemory(context.desc, frame, width, height,
                               {caustics, godRays, physical, objects, tile}, error);
  if (r != Result::Ok) return r;
  if (tile) {  // built on first use; a failure changes nothing
    if (!context.tileIrradianceReady) {
      r = context.tileIrradiance.init(detail::shaderDefines(context.desc), error);
      if (r != Result::Ok) return r;
      context.tileIrradianceReady = true;
    }
    const detail::TileIrradianceLayout layout = detail::tileIrradianceLayout(frame);
    r = context.caustics.ensureTileProgram(layout.groups, layout.cascadeMask, tileVariant, error);
    if (r != Result::Ok) return r;
  }

  detail::GlStateGuard guard;
  detail::DrawStateGuard drawState;  // inside: both save the host's values
  DebugGroup group("postfx");
  // Every resource the frame needs is allocated, and every framebuffer checked, before the
  // first pass adds light: a failure here leaves the target as it was.
  if (fullScreen) {
    r = context.caustics.prepare(frame, textures, block, error);
    if (r != Result::Ok) return r;
  }
  if (physical) {
    r = context.irradiance.reserve(frame, error);
    if (r != Result::Ok) {
      context.caustics.finish();
      return r;
    }
  }
  if (tile) {
    r = context.tileIrradiance.reserve(frame, error);
    if (r != Result::Ok) {
      context.caustics.finish();
      return r;
    }
  }
  if (godRays) {
    r = context.godRays.prepare(frame, width, height, godBlock, error);
    if (r != Result::Ok) {
      context.caustics.finish();
      return r;
    }
  }
  if (objects) {
    r = context.objectCaustics.prepare(frame, light, objectBlock, error);
    if (r != Result::Ok) {
      if (godRays) context.godRays.finish();
      if (fullScreen) context.caustics.finish();
      return r;
    }
  }

  context.timers.beginFrame();
  if (hasFeature(context.desc.features, Feature::PhysicalCaustics)) {
    const double clamped = context.irradiance.pollClampCounts();
    if (clamped >= 0.0) context.timers.setClampedFluxFraction(clamped);
    if (!physical) {
      context.timers.markSkipped(Pass::CausticsIrradiance);
      if (frame.caustics.model == CausticsModel::RayDeviation)
        context.timers.setClampedFluxFraction(0.0);
    }
  }
  if (!tile) context.timers.markSkipped(Pass::CausticsTileIrradiance);
  if (!caustics) {
    context.timers.markSkipped(Pass::Caustics);
    context.caustics.clearRaw(width, height);
  }
  if (!godRays) context.timers.markSkipped(Pass::GodRays);
  if (!objects) context.timers.markSkipped(Pass::ObjectCaustics);
  if (!fullScreen && floor) context.timers.markSkipped(Pass::Floor);

  if (fullScreen) {
    // The god rays draw under the caustics pass's state (its units, samplers and block).
    const GLuint irradiance = physical ? context.irradiance.texture() : 0;
    context.caustics.bindState(frame, textures, irradiance);
    if (physical) {
      // Before the floor and the caustics: both sample its result. Draws into its own
      // framebuffer, then the caustics pass's state is set again.
      DebugGroup irradianceGroup("postfx.caustics_irradiance");
      if (floor) glFinish();
      context.timers.begin(Pass::CausticsIrradiance);
      context.irradiance.draw(frame, textures);
      context.timers.end(Pass::CausticsIrradiance);
      context.caustics.bindState(frame, textures, context.irradiance.texture());
    }
    if (tile) {
      // Before the floor and the caustics, like the window model's irradiance.
      DebugGroup tileGroup("postfx.caustics_tile_irradiance");
      if (floor) glFinish();
      context.timers.begin(Pass::CausticsTileIrradiance);
      context.tileIrradiance.draw(frame, textures);
      context.timers.end(Pass::CausticsTileIrradiance);
      context.caustics.bindState(frame, textures, 0, context.tileIrradiance.texture());
    }
    // Benchmark mode only (BenchmarkFloor): the GPU is drained before each timed pass.
    // Tile-based and software rasterizers (llvmpipe) otherwise run both draws interleaved per
    // tile and no query pair can separate them. This is the one place the plugin waits, and
    // normal frames never get here.
    if (floor) {
      DebugGroup floorGroup("postfx.floor");
      glFinish();
      context.timers.begin(Pass::Floor);
      context.caustics.drawFloor();
      context.timers.end(Pass::Floor);
    }
    if (caustics) {
      DebugGroup causticsGroup("postfx.caustics");
      if (floor) glFinish();
      context.timers.begin(Pass::Caustics);
      context.caustics.drawCaustics(tileVariant);
      context.timers.end(Pass::Caustics);
    }
    if (godRays) {
      DebugGroup godRaysGroup("postfx.god_rays");
      if (floor) glFinish();
      context.timers.begin(Pass::GodRays);
      context.godRays.draw(frame, width, height);
      context.timers.end(Pass::GodRays);
      context.godRays.finish();
      context.godRayPivot = pivot;
    }
    context.caustics.finish();
  }
  if (objects) drawObjectCaustics(context, frame, width, height);
  context.timers.endFrame();
  return Result::Ok;
}

}  // namespace

const char* toString(Pass pass) noexcept {
  switch (pass) {
    case Pass::CausticsIrradiance:
      return "caustics_irradiance";
    case Pass::CausticsTileIrradiance:
      return "caustics_tile_irradiance";
    case Pass::Floor:
      return "floor";
    case Pass::Caustics:
      return "caustics";
    case Pass::GodRays:
      return "god_rays";
    case Pass::ObjectCaustics:
      return "object_caustics";
  }
  return "unknown";
}

const char* toString(Result result) noexcept {
  switch (result) {
    case Result::Ok:
      return "Ok";
    case Result::InvalidArgument:
      return "InvalidArgument";
    case Result::MissingTexture:
      return "MissingTexture";
    case Result::UnsupportedFormat:
      return "UnsupportedFormat";
    case Result::SizeMismatch:
      return "SizeMismatch";
    case Result::ShaderCompileFailed:
      return "ShaderCompileFailed";
    case Result::GlError:
      return "GlError";
    case Result::OutOfMemory:
      return "OutOfMemory";
    case Result::NoContext:
      return "NoContext";
  }
  return "Unknown";
}

Result create(const CreateDesc& desc, Context*& out) noexcept {
  out = nullptr;
  try {
    createError.clear();
    Result r = detail::validateCreateDesc(desc, createError);
    if (r != Result::Ok) return r;
    // Any GL call through epoxy without a context aborts the process: refuse instead.
    if (!glkit::hasCurrentContext()) {
      createError = "create: no current GL context on this thread";
      return Result::NoContext;
    }
    auto context = std::make_unique<Context>();
    context->desc = desc;
    r = context->caustics.init(desc, createError);
    if (r != Result::Ok) return r;
    std::array<bool, kPassCount> present{};
    present[int(Pass::Caustics)] = hasFeature(desc.features, Feature::Caustics);
    present[int(Pass::Floor)] = hasFeature(desc.features, testing::BenchmarkFloor);
    // TileIrradiance needs no feature of its own: its pre-pass exists wherever caustics do.
    present[int(Pass::CausticsTileIrradiance)] = hasFeature(desc.features, Feature::Caustics);
    if (hasFeature(desc.features, Feature::GodRays)) {
      r = context->godRays.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      present[int(Pass::GodRays)] = true;
    }
    if (hasFeature(desc.features, Feature::PhysicalCaustics)) {
      r = context->irradiance.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      present[int(Pass::CausticsIrradiance)] = true;
    }
    if (hasFeature(desc.features, Feature::ObjectCaustics)) {
      r = context->objectCaustics.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      present[int(Pass::ObjectCaustics)] = true;
    }
    context->timers.init(present);
    out = context.release();
    return Result::Ok;
  } catch (const std::bad_alloc&) {
    createError = "out of memory";
    return Result::OutOfMemory;
  } catch (...) {
    createError = "internal error";
    return Result::GlError;
  }
}

Result dispatch(Context& context, const FrameDesc& desc) noexcept {
  try {
    context.error.clear();
    if (!glkit::hasCurrentContext()) {
      context.error = "dispatch: no current GL context on this thread";
      return Result::NoContext;
    }
    return dispatchUnchecked(context, desc);
  } catch (const std::bad_alloc&) {
    context.error = "out of memory";
    return Result::OutOfMemory;
  } catch (...) {
    context.error = "internal error";
    return Result::GlError;
  }
}

void destroy(Context* context) noexcept {
  // Without a current context the GL objects cannot be deleted and trying would abort inside
  // epoxy; they are leaked instead (they die with the GL context that owns them).
  if (context != nullptr && glkit::hasCurrentContext()) delete context;
}

const char* lastError(const Context* context) noexcept {
  return context != nullptr ? context->error.c_str() : createError.c_str();
}

const FrameStats& stats(const Context& context) noexcept {
  return context.timers.stats();
}

ObjectCausticMap objectCausticMap(const Context& context) noexcept {
  return context.objectCaustics.map();
}

namespace testing {

GlName rawCausticTexture(const Context& context) noexcept {
  return context.caustics.rawTexture();
}

CausticIrradianceInfo causticIrradiance(const Context& context) noexcept {
  CausticIrradianceInfo info;
  const detail::IrradianceLayout& l = context.irradiance.layout();
  info.texture = context.irradiance.texture();
  if (info.texture == 0) return info;
  info.resolution = l.resolution;
  info.layers = l.layers;
  info.windowOrigin = l.windowOrigin;
  info.windowSize = l.windowSize;
  for (int k = 0; k < l.layers && k < detail::kMaxIrradianceLayers; ++k)
    info.layerDepth[k] = static_cast<float>(l.depth[k]);
  return info;
}

Result setGodRaySampling(Context& context, GodRaySampling sampling) noexcept {
  if (sampling != GodRaySampling::WorldGrid && sampling != GodRaySampling::UniformAlongRay) {
    context.error = "setGodRaySampling: not a GodRaySampling";
    return Result::InvalidArgument;
  }
  context.error.clear();
  context.godRaySampling = sampling;
  return Result::Ok;
}

}  // namespace testing

}  // namespace postfx
