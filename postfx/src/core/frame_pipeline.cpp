// The frame pipeline behind dispatch (see frame_pipeline.h).
#include "core/frame_pipeline.h"

#include <postfx/testing.h>

#include <optional>
#include <string>

#include "core/block_check.h"
#include "core/context.h"
#include "core/draw_state_guard.h"
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
#include "seabed_caustics/caustics_constants.h"

namespace postfx::detail {
namespace {

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
Result validateFrame(const Context& context, const FrameDesc& frame, ValidatedTextures& textures,
                     std::string& error) {
  Result r = validateFrameValues(context.desc, frame, error);
  if (r != Result::Ok) return r;
  r = validateFrameTextures(context.desc, frame, textures, error);
  if (r != Result::Ok) return r;
  if (hasFeature(context.desc.features, Feature::ObjectCaustics)) {
    r = validateObjectCaustics(context.desc, frame, error);
    if (r != Result::Ok) return r;
  }
  return checkHostDrawState(error);
}

// Every constant the GPU will see this frame.
struct FrameBlocks {
  shared::CausticsBlock caustics{};
  shared::GodRaysBlock godRays{};
  // The one piece of per-frame state that shapes the image: a copy moves with this frame and is
  // kept only once the frame has been drawn, so a refused frame leaves no trace.
  GodRayGridPivot pivot;
  ObjectCausticsViews objects;
};

// Builds and checks the blocks before any GL work.
Result buildBlocks(const Context& context, const FrameDesc& frame, const FramePlan& plan,
                   const ValidatedTextures& textures, FrameBlocks& blocks, std::string& error) {
  const int width = textures.width, height = textures.height;
  blocks.caustics = buildCausticsBlock(context.desc, frame, width, height, textures.water);
  if (plan.fullScreen && !allFinite(blocks.caustics))
    return refuse(error,
                  "frame: a caustics constant overflows the GPU's float (camera.projection, or "
                  "shadow.worldToLightClip about camera.position, has entries too large)");
  blocks.pivot = context.godRayPivot;
  if (plan.godRays) {
    blocks.godRays =
        buildGodRaysBlock(frame, width, height, blocks.pivot,
                          context.godRaySampling == testing::GodRaySampling::UniformAlongRay,
                          context.godRayUniformPhase);
    if (!allFinite(blocks.godRays))
      return refuse(error, "frame: a god-ray constant overflows the GPU's float");
  }
  ObjectCausticsViews& views = blocks.objects;
  if (plan.objects) {
    views.sun = true;
    views.sunFrame = fitObjectLightFrame(frame);
    views.sunBlock = buildObjectCausticsBlock(context.desc, frame, views.sunFrame, width, height);
    if (!allFinite(views.sunBlock) || !casterMatricesFinite(frame, views.sunFrame))
      return refuse(error,
                    "frame: an object-caustics constant overflows the GPU's float "
                    "(objectCaustics.receivers.worldToLightClip or a caster's modelToWorld has "
                    "entries too large)");
  }
  for (int k = 0; k < plan.lightCount; ++k) {
    const int i = plan.lights[static_cast<std::size_t>(k)];
    ObjectLightFrame view;
    fitLocalLightFrame(frame, i, view);
    views.lights.push_back(view);
    views.lightBlocks.push_back(buildObjectCausticsBlock(context.desc, frame, view, width, height));
    if (!allFinite(views.lightBlocks.back()) || !casterMatricesFinite(frame, view)) {
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
Result ensureTileIrradiance(Context& context, const FrameDesc& frame, const FramePlan& plan,
                            TileVariants& variants, std::string& error) {
  if (!context.tileIrradianceReady) {
    const Result r = context.tileIrradiance.init(shaderDefines(context.desc), error);
    if (r != Result::Ok) return r;
    context.tileIrradianceReady = true;
  }
  const TileIrradianceLayout layout = tileIrradianceLayout(frame);
  if (plan.caustics) {
    // The TileIrradiance model may look the field up at half resolution; the window continued
    // by it looks it up per pixel (only in its outer band and beyond).
    const bool reduced = !plan.wavefrontAreaRatio &&
                         frame.caustics.tileLookupResolution == CausticsLookupResolution::Half;
    const Result r =
        context.caustics.ensureTileProgram(layout.groups, layout.cascadeMask, reduced,
                                           plan.wavefrontAreaRatio, variants.caustics, error);
    if (r != Result::Ok) return r;
  }
  // The shafts read the seabed's light: the tile field, or the WavefrontAreaRatio window
  // continued by it.
  if (plan.godRays)
    return context.godRays.ensureTileProgram(layout.groups, layout.cascadeMask,
                                             plan.wavefrontAreaRatio, variants.godRays, error);
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
Result reserve(Context& context, const FrameDesc& frame, const FramePlan& plan,
               const ValidatedTextures& textures, const FrameBlocks& blocks, HeldTargets& held,
               std::string& error) {
  Result r = Result::Ok;
  if (plan.fullScreen) {
    r = context.caustics.prepare(frame, textures, blocks.caustics, error);
    if (r != Result::Ok) return r;
    held.caustics = true;
  }
  if (plan.wavefrontAreaRatio) {
    r = context.wavefrontAreaRatio.reserve(frame, error);
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
  explicit TimedFrame(GpuTimers& timers) : timers_(timers) { timers_.beginFrame(); }
  ~TimedFrame() { timers_.endFrame(); }
  TimedFrame(const TimedFrame&) = delete;
  TimedFrame& operator=(const TimedFrame&) = delete;

 private:
  GpuTimers& timers_;
};

// One timed pass: its debug group, its timer queries around `work`.
// Benchmark mode only (BenchmarkFloor): the GPU is drained before each timed pass. Tile-based
// and software rasterizers (llvmpipe) otherwise run consecutive draws interleaved per tile and
// no query pair can separate them. This is the one place the plugin waits, and normal frames
// never get here.
template <typename Work>
void timedPass(Context& context, const FramePlan& plan, Pass pass, const char* group, Work&& work) {
  DebugGroup debugGroup(group);
  if (plan.floor) glFinish();
  context.timers.begin(pass);
  work();
  context.timers.end(pass);
}

// Whether `pass` draws under the seabed caustics pass's framebuffer and state (the full-screen
// passes and the seabed's pre-passes, which set that state again with their result).
bool drawsUnderSeabedState(Pass pass) {
  return pass != Pass::ObjectCaustics;
}

// Records one planned pass.
void recordPass(Context& context, const FrameDesc& frame, const FramePlan& plan,
                const ValidatedTextures& textures, const FrameBlocks& blocks,
                const TileVariants& tile, const PlannedPass& step, GLuint irradiance) {
  const int w = textures.width, h = textures.height;
  switch (step.pass) {
    case Pass::WavefrontAreaRatio:
      timedPass(context, plan, step.pass, "postfx.wavefront_area_ratio",
                [&] { context.wavefrontAreaRatio.draw(frame, textures); });
      context.caustics.bindState(frame, textures, context.wavefrontAreaRatio.texture());
      return;
    case Pass::TileIrradiance:
      timedPass(context, plan, step.pass, "postfx.tile_irradiance",
                [&] { context.tileIrradiance.draw(frame, textures); });
      context.caustics.bindState(frame, textures, irradiance, context.tileIrradiance.texture());
      return;
    case Pass::Floor:
      timedPass(context, plan, step.pass, "postfx.floor", [&] { context.caustics.drawFloor(); });
      return;
    case Pass::Caustics:
      timedPass(context, plan, step.pass, "postfx.caustics",
                [&] { context.caustics.drawCaustics(tile.caustics); });
      return;
    case Pass::GodRays:
      timedPass(context, plan, step.pass, "postfx.god_rays",
                [&] { context.godRays.draw(frame, w, h, tile.godRays); });
      context.godRayPivot = blocks.pivot;
      return;
    case Pass::ObjectCaustics:
      if (step.light < 0) {
        timedPass(context, plan, step.pass, "postfx.object_caustics",
                  [&] { context.objectCaustics.drawSun(frame, w, h); });
        return;
      }
      // A local light's: timed in its own slot of the light timers.
      DebugGroup debugGroup("postfx.object_caustics_light");
      if (plan.floor) glFinish();
      context.timers.beginLight(step.light);
      context.objectCaustics.drawLight(frame, step.slot, w, h);
      context.timers.endLight(step.light);
      return;
  }
}

// Records the planned passes, in the plan's order, into the host's target.
void record(Context& context, const FrameDesc& frame, const FramePlan& plan,
            const ValidatedTextures& textures, const FrameBlocks& blocks, const TileVariants& tile,
            HeldTargets& held) {
  TimedFrame timedFrame(context.timers);
  if (hasFeature(context.desc.features, Feature::WavefrontAreaRatio)) {
    const double clamped = context.wavefrontAreaRatio.pollClampCounts();
    if (clamped >= 0.0) context.timers.setClampedFluxFraction(clamped);
    if (!plan.wavefrontAreaRatio && frame.caustics.model == CausticsModel::RayDeviation)
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

  // The seabed's passes share the caustics pass's state (its units, samplers and block), set
  // before the first of them; each pre-pass draws into its own framebuffer and sets that state
  // again with its result, which the floor, the caustics and the god rays sample. The object
  // caustics draw after them under their own state.
  const GLuint irradiance = plan.wavefrontAreaRatio ? context.wavefrontAreaRatio.texture() : 0;
  bool seabedState = false;
  std::optional<ObjectCausticsStateGuard> objectState;
  for (const PlannedPass& step : plan.passes()) {
    if (drawsUnderSeabedState(step.pass)) {
      if (!seabedState) context.caustics.bindState(frame, textures, irradiance);
      seabedState = true;
    } else if (!objectState) {
      held.release();  // the seabed's passes are done with the host's target
      objectState.emplace();
      context.objectCaustics.setDrawState();
    }
    recordPass(context, frame, plan, textures, blocks, tile, step, irradiance);
  }
  held.release();
  if (objectState) context.objectCaustics.finishDraws();
}

}  // namespace

Result dispatchFrame(Context& context, const FrameDesc& frame) {
  std::string& error = context.error;
  ValidatedTextures textures;
  Result r = validateFrame(context, frame, textures, error);
  if (r != Result::Ok) return r;
  const FramePlan plan = planFrame(context, frame);
  FrameBlocks blocks;
  r = buildBlocks(context, frame, plan, textures, blocks, error);
  if (r != Result::Ok) return r;
  r = checkFrameMemory(context.desc, frame, textures.width, textures.height, plan, error);
  if (r != Result::Ok) return r;
  r = checkObjectCausticsWork(context.desc, frame, plan, error);
  if (r != Result::Ok) return r;
  TileVariants tile;  // all 0: another model
  if (plan.tile) {
    r = ensureTileIrradiance(context, frame, plan, tile, error);
    if (r != Result::Ok) return r;
  }

  GlStateGuard guard;
  DrawStateGuard drawState;  // inside: both save the host's values
  DebugGroup group("postfx");
  HeldTargets held(context);
  r = reserve(context, frame, plan, textures, blocks, held, error);
  if (r != Result::Ok) return r;
  record(context, frame, plan, textures, blocks, tile, held);
  return Result::Ok;
}

}  // namespace postfx::detail
