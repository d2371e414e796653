// The frame pipeline behind dispatch (see frame_pipeline.h).
#include "core/frame_pipeline.h"

#include <postfx/testing.h>

#include <memory>
#include <string>
#include <vector>

#include "core/block_check.h"
#include "core/context.h"
#include "core/draw_state_guard.h"
#include "core/frame_plan.h"
#include "core/gl_state_guard.h"
#include "core/memory_estimate.h"
#include "core/validation.h"
#include "core/view_state.h"
#include "core/view_validation.h"
#include "god_rays/godrays_constants.h"
#include "object_caustics/object_caustics_frame.h"
#include "object_caustics/object_caustics_light_frame.h"
#include "object_caustics/object_caustics_state.h"
#include "object_caustics/object_caustics_validation.h"
#include "object_caustics/object_caustics_work.h"
#include "seabed_caustics/caustics_constants.h"
#include "seabed_caustics/local_water_layout.h"

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

// The TileIrradiance programs of a view's passes that read the field (0: another model).
struct TileVariants {
  int caustics = 0, godRays = 0;
};

// One view's share of the frame: the frame with the view's camera, G-buffer and target, its
// rectangle, its plan and constants, and its programs.
struct ViewWork {
  View* view = nullptr;
  FrameDesc frame;
  ValidatedTextures textures;
  FramePlan plan;
  shared::CausticsBlock caustics{};
  shared::GodRaysBlock godRays{};
  // The one piece of per-view state that shapes the image: a copy moves with this frame and is
  // kept only once the frame has been drawn, so a refused frame leaves no trace.
  GodRayGridPivot pivot;
  TileVariants tile;  // all 0: another model
};

// The work every view shares: whether the tile field and the window are computed (for any
// view), and the object caustics' views (the first view's plan: they do not depend on the
// camera).
struct SharedWork {
  bool tile = false;
  bool localWater = false;
  bool wavefrontAreaRatio = false;
  bool reflected = false;  // some view draws the reflected caustics
  const FramePlan* objectPlan = nullptr;
  ObjectCausticsViews objects;
  std::vector<ObjectCausticsTarget> targets;
};

// Everything dispatch accepts before it looks at the frame's work: values, textures, casters
// and the host's draw state.
Result validateFrame(const Context& context, const FrameDesc& frame, ValidatedTextures& textures,
                     std::string& error) {
  Result r = validateFrameValues(context.desc, frame, error);
  if (r != Result::Ok) return r;
  r = validateFrameTextures(context.desc, frame, textures, error);
  if (r != Result::Ok) return r;
  if (hasFeature(context.desc.features, Feature::ObjectCaustics))
    return validateObjectCaustics(context.desc, frame, error);
  return Result::Ok;
}

// Builds and checks a view's blocks before any GL work.
Result buildViewBlocks(const Context& context, ViewWork& w, std::string& error) {
  const FrameDesc& frame = w.frame;
  const int width = w.textures.width, height = w.textures.height;
  const glm::vec4 origin(float(w.textures.x), float(w.textures.y), 0.0f, 0.0f);
  w.caustics = buildCausticsBlock(context.desc, frame, width, height, w.textures.water);
  w.caustics.viewOrigin = origin;
  if (w.plan.fullScreen && !allFinite(w.caustics))
    return refuse(error,
                  "frame: a caustics constant overflows the GPU's float (camera.projection, or "
                  "shadow.worldToLightClip about camera.position, has entries too large)");
  if (w.plan.localWater && !allFinite(buildLocalWaterBlock(frame)))
    return refuse(error, "frame: a local water constant overflows the GPU's float");
  w.pivot = w.view->godRayPivot;
  if (w.plan.godRays) {
    w.godRays =
        buildGodRaysBlock(frame, width, height, w.pivot,
                          context.godRaySampling == testing::GodRaySampling::UniformAlongRay,
                          context.godRayUniformPhase);
    if (!allFinite(w.godRays))
      return refuse(error, "frame: a god-ray constant overflows the GPU's float");
  }
  return Result::Ok;
}

// The object caustics' views, fitted once, and every camera view's blocks.
Result buildObjectBlocks(const Context& context, std::span<const ViewWork> work, SharedWork& s,
                         std::string& error) {
  const FramePlan& plan = *s.objectPlan;
  const FrameDesc& first = work[0].frame;
  ObjectCausticsViews& views = s.objects;
  if (plan.objects) {
    views.sun = true;
    views.sunFrame = fitObjectLightFrame(first);
  }
  views.volume = volumeCausticsOn(context.desc, first);
  for (int k = 0; k < plan.lightCount; ++k) {
    ObjectLightFrame view;
    fitLocalLightFrame(first, plan.lights[static_cast<std::size_t>(k)], view);
    views.lights.push_back(view);
  }
  for (std::size_t v = 0; v < work.size(); ++v) {
    const ViewWork& w = work[v];
    const int width = w.textures.width, height = w.textures.height;
    const glm::vec4 origin(float(w.textures.x), float(w.textures.y), 0.0f, 0.0f);
    shared::ObjectCausticsBlock sun{};
    if (plan.objects) {
      sun = buildObjectCausticsBlock(context.desc, w.frame, views.sunFrame, width, height);
      sun.viewOrigin = origin;
      if (!allFinite(sun) || !casterMatricesFinite(w.frame, views.sunFrame))
        return refuse(error,
                      "frame: an object-caustics constant overflows the GPU's float "
                      "(objectCaustics.receivers.worldToLightClip or a caster's modelToWorld has "
                      "entries too large)");
    }
    views.blocks.push_back(sun);
    for (int k = 0; k < plan.lightCount; ++k) {
      const int i = plan.lights[static_cast<std::size_t>(k)];
      const ObjectLightFrame& view = views.lights[static_cast<std::size_t>(k)];
      views.blocks.push_back(buildObjectCausticsBlock(context.desc, w.frame, view, width, height));
      views.blocks.back().viewOrigin = origin;
      if (!allFinite(views.blocks.back()) || !casterMatricesFinite(w.frame, view)) {
        error = "frame: an object-caustics constant of objectCaustics.lights[" + std::to_string(i) +
                "] overflows the GPU's float (its receivers.worldToLightClip, or a caster's "
                "modelToWorld, has entries too large)";
        return Result::InvalidArgument;
      }
    }
    s.targets.push_back({&w.frame, w.textures});
  }
  return Result::Ok;
}

// The TileIrradiance programs of this frame's cascades, each built on first use: the pre-pass,
// and the variants of the passes that read its field (0 for a pass that does not draw).
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

  bool caustics = false, godRays = false, objects = false, reflected = false;
  void release() {
    if (reflected) context_.reflected.finish();
    if (godRays) context_.godRays.finish();
    if (caustics) context_.caustics.finish();
    if (objects) context_.objectCaustics.finishDraws();
    caustics = godRays = objects = reflected = false;
  }

 private:
  Context& context_;
};

// Attaches one view's target to the seabed passes' framebuffers (sizing the view's textures)
// and uploads its blocks.
Result prepareView(Context& context, ViewWork& w, HeldTargets& held, std::string& error) {
  if (w.plan.fullScreen) {
    const Result r =
        context.caustics.prepare(w.frame, w.textures, w.caustics, w.view->caustics, error);
    if (r != Result::Ok) return r;
    held.caustics = true;
  }
  if (w.plan.godRays) {
    const Result r =
        context.godRays.prepare(w.frame, w.textures, w.godRays, w.view->godRays, error);
    if (r != Result::Ok) return r;
    held.godRays = true;
  }
  if (w.plan.reflected) {
    const Result r = context.reflected.prepare(w.frame, error);
    if (r != Result::Ok) return r;
    held.reflected = true;
  }
  return Result::Ok;
}

// Allocates every resource the frame needs, and checks every framebuffer of every view, before
// the first pass adds light: a failure here leaves every target as it was.
Result reserve(Context& context, std::span<ViewWork> work, SharedWork& s, HeldTargets& held,
               std::string& error) {
  const FrameDesc& first = work[0].frame;
  Result r = Result::Ok;
  for (ViewWork& w : work) {
    r = prepareView(context, w, held, error);
    if (r != Result::Ok) return r;
    held.release();
  }
  if (s.wavefrontAreaRatio) {
    r = context.wavefrontAreaRatio.reserve(first, error);
    if (r != Result::Ok) return r;
  }
  if (s.tile) {
    r = context.tileIrradiance.reserve(first, error);
    if (r != Result::Ok) return r;
  }
  if (s.reflected) {
    r = context.reflected.reserve(first, work[0].textures.targetWidth,
                                  work[0].textures.targetHeight, error);
    if (r != Result::Ok) return r;
  } else if (context.reflected.ready()) {
    context.reflected.release();  // a frame without the pass holds none of its memory
  }
  if (s.localWater) {
    r = context.localWater.reserve(first, error);
    if (r != Result::Ok) return r;
  } else if (context.localWater.ready()) {
    context.localWater.release();  // a frame without regions holds none of their memory
  }
  if (s.objectPlan->objectMaps()) {
    held.objects = true;
    r = context.objectCaustics.prepare(first, s.objects, s.targets, error);
  }
  return r;
}

// The frame's slot in a set of timers, closed on every way out of recording.
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
void timedPass(GpuTimers& timers, bool floor, Pass pass, const char* group, Work&& work) {
  DebugGroup debugGroup(group);
  WorkScope account(timers.work(), pass);
  if (floor) glFinish();
  timers.begin(pass);
  work();
  timers.end(pass);
}

// Records one view's passes (the model's window, the floor, the caustics, the god rays) into its
// target, under the seabed caustics pass's state. The shared tile field is drawn in the first
// view that draws (after its window, as the Pass order says: a single view records exactly what
// a context of its own would), once for all.
void recordView(Context& context, ViewWork& w, const SharedWork& s, bool& tileDrawn,
                bool& localWaterDrawn, HeldTargets& held) {
  const FramePlan& plan = w.plan;
  GpuTimers& timers = w.view->timers;
  if (!plan.caustics) context.caustics.clearRaw(w.textures, w.view->caustics);
  if (!plan.fullScreen) return;
  std::string unused;
  // Checked by reserve(): cannot fail now.
  if (prepareView(context, w, held, unused) != Result::Ok) return;
  const GLuint tile = s.tile ? context.tileIrradiance.texture() : 0;
  const GLuint window = plan.wavefrontAreaRatio ? context.wavefrontAreaRatio.texture() : 0;
  if (plan.wavefrontAreaRatio) {
    context.caustics.bindState(w.frame, w.textures, 0);
    context.wavefrontAreaRatio.place(w.frame);
    timedPass(timers, plan.floor, Pass::WavefrontAreaRatio, "postfx.wavefront_area_ratio",
              [&] { context.wavefrontAreaRatio.draw(w.frame, w.textures); });
  }
  if (s.tile && !tileDrawn) {
    // The field depends on the water and the sun only. It samples the water through the
    // seabed state's unit.
    context.caustics.bindState(w.frame, w.textures, 0);
    timedPass(context.timers, plan.floor, Pass::TileIrradiance, "postfx.tile_irradiance",
              [&] { context.tileIrradiance.draw(w.frame, w.textures); });
    tileDrawn = true;
  }
  if (s.localWater && !localWaterDrawn) {
    // View-independent too (the regions and the sun): once for every view.
    context.caustics.bindState(w.frame, w.textures, 0);
    timedPass(context.timers, plan.floor, Pass::LocalWater, "postfx.local_water",
              [&] { context.localWater.draw(w.frame, w.textures); });
    localWaterDrawn = true;
  }
  context.caustics.bindState(w.frame, w.textures, window, tile);
  // Every view that draws with the feature binds the block: the shaders read its count.
  if (context.localWater.ready()) context.localWater.bind(w.frame, s.localWater);
  if (plan.runs(Pass::Floor))
    timedPass(timers, plan.floor, Pass::Floor, "postfx.floor",
              [&] { context.caustics.drawFloor(); });
  if (plan.caustics)
    timedPass(timers, plan.floor, Pass::Caustics, "postfx.caustics",
              [&] { context.caustics.drawCaustics(w.tile.caustics); });
  if (plan.godRays) {
    timedPass(timers, plan.floor, Pass::GodRays, "postfx.god_rays",
              [&] { context.godRays.draw(w.frame, w.tile.godRays, context.caustics.inputs()); });
  }
  if (plan.reflected) {
    // Its field samples the water through the seabed state's units; its light reads that
    // state's block and G-buffer.
    context.caustics.bindState(w.frame, w.textures, 0);
    timedPass(timers, plan.floor, Pass::ReflectedCaustics, "postfx.reflected_caustics",
              [&] { context.reflected.draw(w.frame, w.textures, context.caustics.inputs()); });
  }
  held.release();  // this view is done with its target
}

// Marks what each set of timers does not run this frame.
void markSkipped(Context& context, std::span<ViewWork> work, const SharedWork& s) {
  for (int p = 0; p < kPassCount; ++p) {
    const Pass pass = Pass(p);
    if (isViewPass(pass)) {
      for (ViewWork& w : work)
        if (!w.plan.runs(pass)) w.view->timers.markSkipped(pass);
    } else if (!(pass == Pass::TileIrradiance ? s.tile
                 : pass == Pass::LocalWater   ? s.localWater
                                              : s.objectPlan->runs(pass))) {
      context.timers.markSkipped(pass);
    }
  }
  const FramePlan& plan = *s.objectPlan;
  for (int i = 0; i < context.desc.maxLocalLights; ++i) {
    context.timers.setLightSkip(i, plan.lightSkip[static_cast<std::size_t>(i)]);
    if (plan.lightSkip[static_cast<std::size_t>(i)] != LightSkip::None)
      context.timers.markLightSkipped(i);
  }
}

// Records the frame: the shared tile field, each view's passes, then the object caustics (their
// maps once, composited into every view).
void record(Context& context, std::span<ViewWork> work, SharedWork& s, HeldTargets& held) {
  TimedFrame sharedFrame(context.timers);
  std::vector<std::unique_ptr<TimedFrame>> viewFrames;
  for (ViewWork& w : work) viewFrames.push_back(std::make_unique<TimedFrame>(w.view->timers));
  const FrameDesc& first = work[0].frame;
  const bool floor = work[0].plan.floor;
  if (hasFeature(context.desc.features, Feature::WavefrontAreaRatio)) {
    const double clamped = context.wavefrontAreaRatio.pollClampCounts();
    if (clamped >= 0.0) context.timers.setClampedFluxFraction(clamped);
    if (!s.wavefrontAreaRatio && first.caustics.model == CausticsModel::RayDeviation)
      context.timers.setClampedFluxFraction(0.0);
  }
  markSkipped(context, work, s);

  bool tileDrawn = false, localWaterDrawn = false;
  for (ViewWork& w : work) {
    recordView(context, w, s, tileDrawn, localWaterDrawn, held);
    w.view->godRayPivot = w.pivot;
  }

  const FramePlan& plan = *s.objectPlan;
  if (!plan.objectMaps()) return;
  ObjectCausticsStateGuard objectState;
  context.objectCaustics.setDrawState();
  if (plan.objects)
    timedPass(context.timers, floor, Pass::ObjectCaustics, "postfx.object_caustics",
              [&] { context.objectCaustics.drawSun(s.targets); });
  for (int k = 0; k < plan.lightCount; ++k) {
    // A local light's: timed in its own slot of the light timers.
    const int light = plan.lights[static_cast<std::size_t>(k)];
    DebugGroup debugGroup("postfx.object_caustics_light");
    WorkScope account(context.timers.work(), Pass::ObjectCaustics, light);
    if (floor) glFinish();
    context.timers.beginLight(light);
    context.objectCaustics.drawLight(s.targets, k);
    context.timers.endLight(light);
  }
  held.release();
}

}  // namespace

Result dispatchFrame(Context& context, const FrameDesc& frame, std::span<const ViewDesc> views,
                     bool listed) {
  std::string& error = context.error;
  Result r = listed ? validateViewList(context, views, error) : Result::Ok;
  if (r != Result::Ok) return r;
  std::vector<ViewWork> work(views.size());
  for (std::size_t i = 0; i < views.size(); ++i) {
    const ViewDesc& v = views[i];
    ViewWork& w = work[i];
    const int index = static_cast<int>(i);
    w.view = v.view;
    w.frame = frame;
    w.frame.depth = v.depth;
    w.frame.normal = v.normal;
    w.frame.albedo = v.albedo;
    w.frame.target = v.target;
    w.frame.camera = v.camera;
    if (v.shadow != nullptr) w.frame.shadow = *v.shadow;
    r = prefixed(validateFrame(context, w.frame, w.textures, error), error, index, listed);
    if (r != Result::Ok) return r;
    r = prefixed(applyViewport(v.viewport, w.textures, error), error, index, listed);
    if (r != Result::Ok) return r;
  }
  std::vector<ViewRect> rects;
  for (const ViewWork& w : work) rects.push_back({w.frame.target.texture, w.textures});
  r = checkViewOverlaps(rects, error);
  if (r != Result::Ok) return r;
  r = checkHostDrawState(error);
  if (r != Result::Ok) return r;

  SharedWork s;
  std::vector<ViewMemory> memory;
  for (std::size_t i = 0; i < work.size(); ++i) {
    ViewWork& w = work[i];
    w.plan = planFrame(context, w.frame);
    s.tile = s.tile || w.plan.tile;
    s.localWater = s.localWater || w.plan.localWater;
    s.wavefrontAreaRatio = s.wavefrontAreaRatio || w.plan.wavefrontAreaRatio;
    s.reflected = s.reflected || w.plan.reflected;
    r = prefixed(buildViewBlocks(context, w, error), error, static_cast<int>(i), listed);
    if (r != Result::Ok) return r;
    memory.push_back({&w.frame, w.textures.targetWidth, w.textures.targetHeight, w.textures.width,
                      w.textures.height, &w.plan});
  }
  s.objectPlan = &work[0].plan;
  r = buildObjectBlocks(context, work, s, error);
  if (r != Result::Ok) return r;
  r = checkFrameMemory(context.desc, memory, error);
  if (r != Result::Ok) return r;
  r = checkObjectCausticsWork(context.desc, work[0].frame, *s.objectPlan, error);
  if (r != Result::Ok) return r;
  for (ViewWork& w : work)
    if (w.plan.tile) {
      r = ensureTileIrradiance(context, w.frame, w.plan, w.tile, error);
      if (r != Result::Ok) return r;
    }

  GlStateGuard guard;
  DrawStateGuard drawState;  // inside: both save the host's values
  DebugGroup group("postfx");
  HeldTargets held(context);
  r = reserve(context, work, s, held, error);
  if (r != Result::Ok) return r;
  record(context, work, s, held);
  return Result::Ok;
}

}  // namespace postfx::detail
