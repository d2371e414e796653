// The public entry points: validation first, GL work only once everything is known good, and
// no exception ever crossing the API boundary.
#include <postfx/postfx.h>

#include <glkit/current_context.h>

#include <memory>
#include <new>

#include "context.h"
#include "frame_constants.h"
#include "gl_state_guard.h"
#include "godrays_constants.h"
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
  return context.objectCausticsPass >= 0 && o.settings.enabled && o.casterCount > 0 &&
         o.settings.intensity > 0.0f && frame.sun.direction.y > 0.0 &&
         detail::castersInReceiverView(o);
}

// The object caustics, timed as their own pass, after the seabed caustics and god rays.
Result runObjectCaustics(Context& context, const FrameDesc& frame, int width, int height) {
  const detail::ObjectLightFrame light = detail::fitObjectLightFrame(frame);
  const shared::ObjectCausticsBlock block =
      detail::buildObjectCausticsBlock(context.desc, frame, light, width, height);
  const Result r = context.objectCaustics.prepare(frame, light, block, context.error);
  if (r != Result::Ok) return r;
  DebugGroup group("postfx.object_caustics");
  if (hasFeature(context.desc.features, Feature::BenchmarkFloor)) glFinish();
  context.timers.begin(context.objectCausticsPass);
  context.objectCaustics.draw(frame, width, height);
  context.timers.end(context.objectCausticsPass);
  return Result::Ok;
}

Result dispatchUnchecked(Context& context, const FrameDesc& frame) {
  std::string& error = context.error;
  Result r = detail::validateFrameValues(context.desc, frame, error);
  if (r != Result::Ok) return r;
  detail::ValidatedTextures textures;
  r = detail::validateFrameTextures(context.desc, frame, textures, error);
  if (r != Result::Ok) return r;
  if (context.objectCausticsPass >= 0) {
    r = detail::validateObjectCaustics(frame, error);
    if (r != Result::Ok) return r;
  }

  const bool caustics = causticsHaveWork(context, frame);
  const bool godRays = godRaysHaveWork(context, frame);
  const bool physical = caustics && detail::physicalCausticsActive(context.desc, frame);
  const bool floor = hasFeature(context.desc.features, Feature::BenchmarkFloor);
  const bool objects = objectCausticsHaveWork(context, frame);
  const shared::CausticsBlock block = detail::buildCausticsBlock(
      context.desc, frame, textures.width, textures.height, textures.water);

  detail::GlStateGuard guard;
  DebugGroup group("postfx");
  context.timers.beginFrame();
  if (context.irradiancePass >= 0) {
    const double clamped = context.irradiance.pollClampCounts();
    if (clamped >= 0.0) context.timers.setClampedFluxFraction(clamped);
    if (!physical) {
      context.timers.markSkipped(context.irradiancePass);
      if (frame.caustics.model == CausticsModel::Seed002)
        context.timers.setClampedFluxFraction(0.0);
    }
  }
  if (!caustics) {
    context.timers.markSkipped(Context::kCausticsPass);
    context.caustics.clearRaw(textures.width, textures.height);
  }
  if (!godRays && context.godRaysPass >= 0) context.timers.markSkipped(context.godRaysPass);
  if (!objects && context.objectCausticsPass >= 0)
    context.timers.markSkipped(context.objectCausticsPass);
  // The floor runs whenever some timed pass does, so that every pass has its ratio.
  if (!caustics && !godRays && !(objects && floor)) {
    if (floor) context.timers.markSkipped(Context::kFloorPass);
    r = objects ? runObjectCaustics(context, frame, textures.width, textures.height) : Result::Ok;
    context.timers.endFrame();
    return r;
  }
  // The god rays draw under the caustics pass's state (its units, samplers and block).
  r = context.caustics.prepare(frame, textures, block, error);
  if (r != Result::Ok) {
    context.timers.endFrame();
    return r;
  }
  if (godRays) {
    const shared::GodRaysBlock godBlock =
        detail::buildGodRaysBlock(frame, textures.width, textures.height, context.godRayPivot);
    r = context.godRays.prepare(frame, textures.width, textures.height, godBlock, error);
    if (r != Result::Ok) {
      context.caustics.finish();
      context.timers.endFrame();
      return r;
    }
  }
  const GLuint irradiance = physical ? context.irradiance.texture() : 0;
  context.caustics.bindState(frame, textures, irradiance);
  if (physical) {
    // Before the floor and the caustics: both sample its result. Draws into its own
    // framebuffer, then the caustics pass's state is set again.
    DebugGroup irradianceGroup("postfx.caustics_irradiance");
    if (floor) glFinish();
    context.timers.begin(context.irradiancePass);
    context.irradiance.draw(frame, textures);
    context.timers.end(context.irradiancePass);
    context.caustics.bindState(frame, textures, context.irradiance.texture());
  }
  // Benchmark mode only (BenchmarkFloor): the GPU is drained before each timed pass. Tile-based
  // and software rasterizers (llvmpipe) otherwise run both draws interleaved per tile and no
  // query pair can separate them. This is the one place the plugin waits, and normal frames
  // never get here.
  if (floor) {
    DebugGroup floorGroup("postfx.floor");
    glFinish();
    context.timers.begin(Context::kFloorPass);
    context.caustics.drawFloor();
    context.timers.end(Context::kFloorPass);
  }
  if (caustics) {
    DebugGroup causticsGroup("postfx.caustics");
    if (floor) glFinish();
    context.timers.begin(Context::kCausticsPass);
    context.caustics.drawCaustics();
    context.timers.end(Context::kCausticsPass);
  }
  if (godRays) {
    DebugGroup godRaysGroup("postfx.god_rays");
    if (floor) glFinish();
    context.timers.begin(context.godRaysPass);
    context.godRays.draw(frame, textures.width, textures.height);
    context.timers.end(context.godRaysPass);
    context.godRays.finish();
  }
  context.caustics.finish();
  r = objects ? runObjectCaustics(context, frame, textures.width, textures.height) : Result::Ok;
  context.timers.endFrame();
  return r;
}

}  // namespace

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
    case Result::NotImplemented:
      return "NotImplemented";
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
    const bool floor = hasFeature(desc.features, Feature::BenchmarkFloor);
    int passCount = floor ? 2 : 1;
    const char* names[kMaxPasses] = {"caustics", "floor", "", "", ""};
    if (hasFeature(desc.features, Feature::GodRays)) {
      r = context->godRays.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      context->godRaysPass = passCount;
      names[passCount++] = "god_rays";
    }
    if (hasFeature(desc.features, Feature::PhysicalCaustics)) {
      r = context->irradiance.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      context->irradiancePass = passCount;
      names[passCount++] = "caustics_irradiance";
    }
    if (hasFeature(desc.features, Feature::ObjectCaustics)) {
      r = context->objectCaustics.init(detail::shaderDefines(desc), createError);
      if (r != Result::Ok) return r;
      context->objectCausticsPass = passCount;
      names[passCount++] = "object_caustics";
    }
    context->timers.init(passCount, names);
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

}  // namespace postfx
