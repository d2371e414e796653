// The public entry points: validation first, GL work only once everything is known good, and
// no exception ever crossing the API boundary.
#include <postfx/postfx.h>
#include <postfx/testing.h>

#include <glkit/current_context.h>

#include <array>
#include <memory>
#include <new>

#include "core/block_check.h"
#include "core/context.h"
#include "core/draw_state_guard.h"
#include "core/frame_constants.h"
#include "core/frame_plan.h"
#include "core/gl_state_guard.h"
#include "core/memory_estimate.h"
#include "core/validation.h"
#include "god_rays/godrays_constants.h"
#include "object_caustics/object_caustics_frame.h"
#include "object_caustics/object_caustics_light_frame.h"
#include "object_caustics/object_caustics_state.h"
#include "object_caustics/object_caustics_validation.h"
#include "object_caustics/object_caustics_work.h"

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

Result refuse(std::string& error, const char* message) {
  error = message;
  return Result::InvalidArgument;
}

// Everything dispatch accepts before it looks at the frame's work: values, textures, casters
// and the host's draw state.
Result validateFrame(const Context& context, const FrameDesc& frame,
                     detail::ValidatedTextures& textures, std::string& error) {
  Result r = detail::validateFrameValues(context.desc, frame, error);
  if (r != Result::Ok) return r;
  r = detail::validateFrameTextures(context.desc, frame, textures, error);
  if (r != Result::Ok) return r;
  if (hasFeature(context.desc.features, Feature::ObjectCaustics)) {
    r = detail::validateObjectCaustics(context.desc, frame, error);
    if (r != Result::Ok) return r;
  }
  return detail::checkHostDrawState(error);
}

// Every constant the GPU will see this frame.
struct FrameBlocks {
  shared::CausticsBlock caustics{};
  shared::GodRaysBlock godRays{};
  // The one piece of per-frame state that shapes the image: a copy moves with this frame and is
  // kept only once the frame has been drawn, so a refused frame leaves no trace.
  detail::GodRayGridPivot pivot;
  detail::ObjectCausticsViews objects;
};

// Builds and checks the blocks before any GL work.
Result buildBlocks(const Context& context, const FrameDesc& frame, const detail::FramePlan& plan,
                   const detail::ValidatedTextures& textures, FrameBlocks& blocks,
                   std::string& error) {
  const int width = textures.width, height = textures.height;
  blocks.caustics = detail::buildCausticsBlock(context.desc, frame, width, height, textures.water);
  if (plan.fullScreen && !detail::allFinite(blocks.caustics))
    return refuse(error,
                  "frame: a caustics constant overflows the GPU's float (camera.projection, or "
                  "shadow.worldToLightClip about camera.position, has entries too large)");
  blocks.pivot = context.godRayPivot;
  if (plan.godRays) {
    blocks.godRays = detail::buildGodRaysBlock(
        frame, width, height, blocks.pivot,
        context.godRaySampling == testing::GodRaySampling::UniformAlongRay,
        context.godRayUniformPhase);
    if (!detail::allFinite(blocks.godRays))
      return refuse(error, "frame: a god-ray constant overflows the GPU's float");
  }
  detail::ObjectCausticsViews& views = blocks.objects;
  if (plan.objects) {
    views.sun = true;
    views.sunFrame = detail::fitObjectLightFrame(frame);
    views.sunBlock =
        detail::buildObjectCausticsBlock(context.desc, frame, views.sunFrame, width, height);
    if (!detail::allFinite(views.sunBlock) || !detail::casterMatricesFinite(frame, views.sunFrame))
      return refuse(error,
                    "frame: an object-caustics constant overflows the GPU's float "
                    "(objectCaustics.receivers.worldToLightClip or a caster's modelToWorld has "
                    "entries too large)");
  }
  for (int k = 0; k < plan.lightCount; ++k) {
    const int i = plan.lights[static_cast<std::size_t>(k)];
    detail::ObjectLightFrame view;
    detail::fitLocalLightFrame(frame, i, view);
    views.lights.push_back(view);
    views.lightBlocks.push_back(
        detail::buildObjectCausticsBlock(context.desc, frame, view, width, height));
    if (!detail::allFinite(views.lightBlocks.back()) ||
        !detail::casterMatricesFinite(frame, view)) {
      error = "frame: an object-caustics constant of objectCaustics.lights[" + std::to_string(i) +
              "] overflows the GPU's float (its receivers.worldToLightClip, or a caster's "
              "modelToWorld, has entries too large)";
      return Result::InvalidArgument;
    }
  }
  return Result::Ok;
}

// The TileIrradiance programs of this frame's cascades, each built on first use: the pre-pass,
// and the variants of the passes that read its field (0 for a pass that does not draw).
struct TileVariants {
  int caustics = 0, godRays = 0;
};

// A failure changes nothing.
Result ensureTileIrradiance(Context& context, const FrameDesc& frame, const detail::FramePlan& plan,
                            TileVariants& variants, std::string& error) {
  if (!context.tileIrradianceReady) {
    const Result r = context.tileIrradiance.init(detail::shaderDefines(context.desc), error);
    if (r != Result::Ok) return r;
    context.tileIrradianceReady = true;
  }
  const detail::TileIrradianceLayout layout = detail::tileIrradianceLayout(frame);
  if (plan.caustics) {
    // The TileIrradiance model may look the field up at half resolution; the window continued
    // by it looks it up per pixel (only in its outer band and beyond).
    const bool reduced =
        !plan.physical && frame.caustics.tileLookupResolution == CausticsLookupResolution::Half;
    const Result r = context.caustics.ensureTileProgram(layout.groups, layout.cascadeMask, reduced,
                                                        plan.physical, variants.caustics, error);
    if (r != Result::Ok) return r;
  }
  // The shafts read the seabed's light: the tile field, or the WavefrontAreaRatio window
  // continued by it.
  if (plan.godRays)
    return context.godRays.ensureTileProgram(layout.groups, layout.cascadeMask, plan.physical,
                                             variants.godRays, error);
  return Result::Ok;
}

// Our framebuffers hold the host's target only within the frame: every pass prepared lets go of
// it on whatever way the frame ends (release() once drawn, else the destructor when a later
// pass could not be prepared).
class HeldTargets {
 public:
  explicit HeldTargets(Context& context) : context_(context) {}
  ~HeldTargets() { release(); }
  HeldTargets(const HeldTargets&) = delete;
  HeldTargets& operator=(const HeldTargets&) = delete;

  bool caustics = false, godRays = false;
  void release() {
    if (godRays) context_.godRays.finish();
    if (caustics) context_.caustics.finish();
    caustics = godRays = false;
  }

 private:
  Context& context_;
};

// Allocates every resource the frame needs, and checks every framebuffer, before the first
// pass adds light: a failure here leaves the target as it was.
Result reserve(Context& context, const FrameDesc& frame, const detail::FramePlan& plan,
               const detail::ValidatedTextures& textures, const FrameBlocks& blocks,
               HeldTargets& held, std::string& error) {
  Result r = Result::Ok;
  if (plan.fullScreen) {
    r = context.caustics.prepare(frame, textures, blocks.caustics, error);
    if (r != Result::Ok) return r;
    held.caustics = true;
  }
  if (plan.physical) {
    r = context.irradiance.reserve(frame, error);
    if (r != Result::Ok) return r;
  }
  if (plan.tile) {
    r = context.tileIrradiance.reserve(frame, error);
    if (r != Result::Ok) return r;
  }
  if (plan.godRays) {
    r = context.godRays.prepare(frame, textures.width, textures.height, blocks.godRays, error);
    if (r != Result::Ok) return r;
    held.godRays = true;
  }
  if (plan.objectMaps()) r = context.objectCaustics.prepare(frame, blocks.objects, error);
  return r;
}

// The frame's slot in the timers, closed on every way out of recording.
class TimedFrame {
 public:
  explicit TimedFrame(detail::GpuTimers& timers) : timers_(timers) { timers_.beginFrame(); }
  ~TimedFrame() { timers_.endFrame(); }
  TimedFrame(const TimedFrame&) = delete;
  TimedFrame& operator=(const TimedFrame&) = delete;

 private:
  detail::GpuTimers& timers_;
};

// One timed pass: its debug group, its timer queries around `work`.
// Benchmark mode only (BenchmarkFloor): the GPU is drained before each timed pass. Tile-based
// and software rasterizers (llvmpipe) otherwise run consecutive draws interleaved per tile and
// no query pair can separate them. This is the one place the plugin waits, and normal frames
// never get here.
template <typename Work>
void timedPass(Context& context, const detail::FramePlan& plan, Pass pass, const char* group,
               Work&& work) {
  DebugGroup debugGroup(group);
  if (plan.floor) glFinish();
  context.timers.begin(pass);
  work();
  context.timers.end(pass);
}

// Records the planned passes into the host's target.
void record(Context& context, const FrameDesc& frame, const detail::FramePlan& plan,
            const detail::ValidatedTextures& textures, const FrameBlocks& blocks,
            const TileVariants& tile, HeldTargets& held) {
  TimedFrame timedFrame(context.timers);
  if (hasFeature(context.desc.features, Feature::PhysicalCaustics)) {
    const double clamped = context.irradiance.pollClampCounts();
    if (clamped >= 0.0) context.timers.setClampedFluxFraction(clamped);
    if (!plan.physical && frame.caustics.model == CausticsModel::RayDeviation)
      context.timers.setClampedFluxFraction(0.0);
  }
  for (int p = 0; p < kPassCount; ++p)
    if (!plan.runs(Pass(p))) context.timers.markSkipped(Pass(p));
  for (int i = 0; i < context.desc.maxLocalLights; ++i) {
    context.timers.setLightSkip(i, plan.lightSkip[static_cast<std::size_t>(i)]);
    if (plan.lightSkip[static_cast<std::size_t>(i)] != LightSkip::None)
      context.timers.markLightSkipped(i);
  }
  if (!plan.caustics) context.caustics.clearRaw(textures.width, textures.height);

  if (plan.fullScreen) {
    // The god rays draw under the caustics pass's state (its units, samplers and block); each
    // pre-pass draws into its own framebuffer, then that state is set again with its result.
    // Both pre-passes run before the floor, the caustics and the god rays: all sample their
    // result (the god rays the same field as the caustics).
    const GLuint irradiance = plan.physical ? context.irradiance.texture() : 0;
    context.caustics.bindState(frame, textures, irradiance);
    if (plan.physical) {
      timedPass(context, plan, Pass::CausticsIrradiance, "postfx.caustics_irradiance",
                [&] { context.irradiance.draw(frame, textures); });
      context.caustics.bindState(frame, textures, context.irradiance.texture());
    }
    if (plan.tile) {
      timedPass(context, plan, Pass::CausticsTileIrradiance, "postfx.caustics_tile_irradiance",
                [&] { context.tileIrradiance.draw(frame, textures); });
      context.caustics.bindState(frame, textures, irradiance, context.tileIrradiance.texture());
    }
    if (plan.floor)
      timedPass(context, plan, Pass::Floor, "postfx.floor", [&] { context.caustics.drawFloor(); });
    if (plan.caustics)
      timedPass(context, plan, Pass::Caustics, "postfx.caustics",
                [&] { context.caustics.drawCaustics(tile.caustics); });
    if (plan.godRays) {
      timedPass(context, plan, Pass::GodRays, "postfx.god_rays", [&] {
        context.godRays.draw(frame, textures.width, textures.height, tile.godRays);
      });
      context.godRayPivot = blocks.pivot;
    }
    held.release();
  }
  // Timed as their own passes, after the seabed caustics and god rays: the sun's, then each
  // local light's.
  if (plan.objectMaps()) {
    detail::ObjectCausticsStateGuard guard;
    context.objectCaustics.setDrawState();
    const int w = textures.width, h = textures.height;
    if (plan.objects)
      timedPass(context, plan, Pass::ObjectCaustics, "postfx.object_caustics",
                [&] { context.objectCaustics.drawSun(frame, w, h); });
    for (int k = 0; k < plan.lightCount; ++k) {
      DebugGroup debugGroup("postfx.object_caustics_light");
      if (plan.floor) glFinish();
      const int i = plan.lights[static_cast<std::size_t>(k)];
      context.timers.beginLight(i);
      context.objectCaustics.drawLight(frame, k, w, h);
      context.timers.endLight(i);
    }
    context.objectCaustics.finishDraws();
  }
}

Result dispatchUnchecked(Context& context, const FrameDesc& frame) {
  std::string& error = context.error;
  detail::ValidatedTextures textures;
  Result r = validateFrame(context, frame, textures, error);
  if (r != Result::Ok) return r;
  const detail::FramePlan plan = detail::planFrame(context, frame);
  FrameBlocks blocks;
  r = buildBlocks(context, frame, plan, textures, blocks, error);
  if (r != Result::Ok) return r;
  r = detail::checkFrameMemory(context.desc, frame, textures.width, textures.height, plan, error);
  if (r != Result::Ok) return r;
  r = detail::checkObjectCausticsWork(context.desc, frame, plan, error);
  if (r != Result::Ok) return r;
  TileVariants tile;  // all 0: another model
  if (plan.tile) {
    r = ensureTileIrradiance(context, frame, plan, tile, error);
    if (r != Result::Ok) return r;
  }

  detail::GlStateGuard guard;
  detail::DrawStateGuard drawState;  // inside: both save the host's values
  DebugGroup group("postfx");
  HeldTargets held(context);
  r = reserve(context, frame, plan, textures, blocks, held, error);
  if (r != Result::Ok) return r;
  record(context, frame, plan, textures, blocks, tile, held);
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
    // TileIrradiance needs no feature of its own: its pre-pass exists wherever caustics or god
    // rays (which read its field) do.
    present[int(Pass::CausticsTileIrradiance)] =
        hasFeature(desc.features, Feature::Caustics) || hasFeature(desc.features, Feature::GodRays);
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
      r = context->objectCaustics.init(detail::shaderDefines(desc), desc.maxLocalLights,
                                       createError);
      if (r != Result::Ok) return r;
      present[int(Pass::ObjectCaustics)] = true;
    }
    context->timers.init(
        present, hasFeature(desc.features, Feature::ObjectCaustics) ? desc.maxLocalLights : 0);
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

LightCausticMap lightCausticMap(const Context& context) noexcept {
  LightCausticMap map;
  map.texture = context.objectCaustics.lightMapTexture();
  map.size = context.objectCaustics.lightMapSize();
  map.worldToMapClip = context.objectCaustics.lightMapClip();
  return map;
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

Result setGodRaySampling(Context& context, GodRaySampling sampling) noexcept {
  if (sampling != GodRaySampling::WorldGrid && sampling != GodRaySampling::UniformAlongRay) {
    context.error = "setGodRaySampling: not a GodRaySampling";
    return Result::InvalidArgument;
  }
  context.error.clear();
  context.godRaySampling = sampling;
  return Result::Ok;
}

Result setGodRayUniformPhase(Context& context, float phase) noexcept {
  if (!(phase >= 0.0f && phase < 1.0f)) {
    context.error = "setGodRayUniformPhase: phase must be in [0, 1)";
    return Result::InvalidArgument;
  }
  context.error.clear();
  context.godRayUniformPhase = phase;
  return Result::Ok;
}

}  // namespace testing

}  // namespace postfx
