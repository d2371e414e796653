#pragma once
// What the plugin reports back: per-pass GPU timings (read from timestamp queries without ever
// waiting on the GPU: a pass's numbers describe a frame a few dispatches old, the ring is
// kTimerRingDepth frames deep) and the message of the last failed call.
#include <cstdint>

#include <postfx/lights.h>

namespace postfx {

struct Context;
struct View;

inline constexpr int kTimerRingDepth = 4;      // frames of timestamp pairs in flight
inline constexpr int kTimerMedianWindow = 64;  // resolved frames the median is taken over

// The timed passes, in the order dispatch() runs them; what each reads, writes and costs:
// docs/passes.md. The model's pre-passes run for the seabed caustics or the god rays.
enum class Pass : std::uint8_t {
  WavefrontAreaRatio,  // WavefrontAreaRatio's window (Feature::WavefrontAreaRatio)
  TileIrradiance,      // TileIrradiance's field (also continues WavefrontAreaRatio's window)
  Floor,               // benchmark floor (testing::BenchmarkFloor, postfx/testing.h)
  Caustics,            // seabed caustics (Feature::Caustics)
  GodRays,             // god rays, march and upsample together (Feature::GodRays)
  ObjectCaustics,      // the sun's object caustics (Feature::ObjectCaustics; lights apart)
  // The local water regions' light (Feature::LocalWater), once per frame for every view. Runs
  // with the pre-passes, before Floor (listed last so that the older passes keep their values).
  LocalWater,
  // The waves' reflected light above the water (Feature::ReflectedCaustics), per view: its
  // field (a window around the view's camera) and the pass that adds it.
  ReflectedCaustics,
  // Former names, kept so that a host compiles while it renames (CHANGELOG.md).
  CausticsIrradiance [[deprecated("renamed Pass::WavefrontAreaRatio")]] = WavefrontAreaRatio,
  CausticsTileIrradiance [[deprecated("renamed Pass::TileIrradiance")]] = TileIrradiance,
};
inline constexpr int kPassCount = 8;

// Stable snake_case name, e.g. "god_rays" for Pass::GodRays; "unknown" outside the enum.
const char* toString(Pass pass) noexcept;

// The work account (CreateDesc::workAccount): what a pass asked of the GPU in a frame, in counts
// that do not depend on the machine, for a cost model to turn into time on any GPU class
// (docs/gpu_cost.md). Where each figure came from, as bits of WorkCounts::sources:
enum WorkSource : std::uint32_t {
  // vertices, primitives, fragments, computeInvocations: the driver's pipeline statistics
  // (GL_ARB_pipeline_statistics_query, core in GL 4.6). Without them vertices and compute
  // invocations are counted from the draw and dispatch sizes, primitives and fragments read 0.
  kWorkFromPipelineStatistics = 1u << 0,
  kWorkFromSamplesPassed = 1u << 1,  // samplesPassed, blendedSamples: GL_SAMPLES_PASSED
  // Invocations, fetches and atomics counted in the shaders (testing::CountShaderWork): exact,
  // but the frame's timings then include the counting.
  kWorkCounted = 1u << 2,
};

// One draw, dispatch or clear's work in a frame, or the sum of a pass's.
struct WorkCounts {
  std::uint64_t draws = 0, dispatches = 0, clears = 0;  // GL calls
  std::uint64_t vertices = 0;                           // vertex shader invocations
  std::uint64_t primitivesSubmitted = 0;                // primitives the draws made
  std::uint64_t primitives = 0;                         // primitives rasterised (after clipping)
  // Fragment shader invocations. The driver's: a GPU counts each fragment shaded; Mesa's llvmpipe
  // counts 16 for every 4x4 block a primitive touches. Counted: fragments shaded, helper lanes
  // of 2x2 quads excluded.
  std::uint64_t fragments = 0;
  std::uint64_t computeInvocations = 0;
  std::uint64_t samplesPassed = 0;   // fragments written (not discarded, depth test passed)
  std::uint64_t blendedSamples = 0;  // of those, blended into their target (read and written)
  // Texture and image reads (texture, textureLod, texelFetch, textureGather, imageLoad: one
  // each, whatever the filter) and atomic operations: each shader's stated count per invocation
  // on its full path (docs/gpu_cost.md; a test holds it to the counted one) times the driver's
  // invocations, or counted.
  std::uint64_t fetches = 0;
  std::uint64_t fragmentFetches = 0;  // of those, the fragment stage's (2x2 quads repeat them)
  std::uint64_t atomics = 0;
  // Memory moved at least once: each texture and buffer read or written (size x format; the
  // host's G-buffer and target within the view's rectangle), render targets per sample written
  // (twice when blended), clears.
  std::uint64_t bytesRead = 0, bytesWritten = 0;
  std::uint32_t sources = 0;  // WorkSource bits
};
// Adds every count of `w` to `sum` (sources OR-ed): a pass's steps, or a frame's passes.
WorkCounts& operator+=(WorkCounts& sum, const WorkCounts& w) noexcept;

struct PassStats {
  bool present = false;       // the context has this pass (its feature was given at create())
  double lastMs = 0.0;        // GPU time of the most recent resolved frame; 0 when skipped
  double medianMs = 0.0;      // median over the last kTimerMedianWindow resolved frames
  bool skipped = false;       // the most recent resolved frame skipped this pass (nothing to do)
  std::uint32_t samples = 0;  // resolved frames in the median window (skipped ones count as 0 ms)
  // With CreateDesc::workAccount: the sum of the pass's steps (workSteps) in the most recent
  // resolved frame; all 0 without it, or when skipped.
  WorkCounts work;
};

// Why a local light (ObjectCausticsFrame::lights) made no object caustics in a frame.
enum class LightSkip : std::uint8_t {
  None,             // it ran
  NoCasterInReach,  // not listed, range or intensity 0, the pass disabled, or no caster within
                    // its range, inside its cone and in its receiver map's view
  InsideCaster,     // the light lies inside a caster's bounding box (no view from it sees
                    // that caster's outside)
  // The light and the casters it reaches lie on opposite sides of the water level: a local
  // light's rays refracted at the water surface are not modelled (the sun's are).
  AcrossWaterSurface,
  // The casters in reach span more than kMaxLightViewDegrees around the light (one perspective
  // view per light cannot hold them; the light is too close to them or among them).
  CastersAround,
};
// The widest view (full apex angle, degrees) a local light's caster maps are drawn with.
inline constexpr double kMaxLightViewDegrees = 160.0;

struct FrameStats {
  PassStats passes[kPassCount];  // indexed by Pass: passes[int(Pass::GodRays)], or pass() below
  const PassStats& pass(Pass p) const noexcept { return passes[static_cast<int>(p)]; }
  // Each local light's object caustics (ObjectCausticsFrame::lights[i]), timed on their own:
  // Pass::ObjectCaustics times the sun's alone. present for i < CreateDesc::maxLocalLights with
  // Feature::ObjectCaustics. A light that makes no caustics is skipped: 0 ms.
  PassStats lights[kMaxLocalLightsLimit];
  const PassStats& objectLight(int i) const noexcept { return lights[i]; }
  // Why each light was skipped in the most recent successful dispatch (None: it ran), for
  // i < CreateDesc::maxLocalLights (a slot past lightCount reads NoCasterInReach; slots past
  // maxLocalLights stay None). Known at once, unlike the timings, which describe a frame a few
  // dispatches old.
  LightSkip lightSkip[kMaxLocalLightsLimit] = {};
  std::uint64_t framesDispatched = 0;  // successful dispatch() calls
  std::uint64_t framesResolved = 0;    // of those, frames whose timings have been read back
  std::uint64_t framesDropped = 0;     // frames whose queries were still pending when the ring
                                       // wrapped (read never, rather than stall)
  // CausticsModel::WavefrontAreaRatio: the flux CausticsSettings::maxIrradiance removed in the
  // most recent frame whose count has been read back (a few dispatches old, never stalled
  // for), as a fraction of the window's flat-water flux summed over the depth layers. With
  // Feature::WavefrontAreaRatio: 0 after a RayDeviation frame, kept as it was by a TileIrradiance
  // frame; -1 until a first count is read, and always without the feature.
  double clampedFluxFraction = -1.0;
};

// Per-pass GPU timings, updated by each dispatch() from queries that have completed.
const FrameStats& stats(const Context& context) noexcept;

// One step of the work account: a draw, dispatch or clear of one of the plugin's programs.
struct WorkStep {
  const char* name = "";  // stable "<pass>.<step>", e.g. "god_rays.march" (docs/gpu_cost.md)
  Pass pass = Pass::Caustics;
  int light = -1;       // ObjectCausticsFrame::lights index of a local light's step, else -1
  int targetBytes = 0;  // bytes per sample of the render targets it writes, 0 for none
  std::uint64_t viewportPixels = 0;  // a draw's viewport area, 0 for a dispatch or a clear
  bool blended = false;              // its render targets are blended (read-modify-write)
  // Its GL program (labelled "postfx.<...>", glGetObjectLabel), 0 for a clear: its shaders'
  // arithmetic is the driver's to report (docs/gpu_cost.md reads it from Mesa's NIR).
  GlName program = 0;
  // The shaders' stated fetches and atomics per invocation (docs/gpu_cost.md) times the step's
  // invocations; statedBound: a data-dependent loop (a march, a blur the data sizes) stated at
  // its longest. Counted (testing::CountShaderWork), work holds what they really did.
  std::uint64_t statedFetches = 0, statedAtomics = 0;
  bool statedBound = false;
  // testing::TimeEachStep: the step alone by the CPU's clock, the GPU drained before and
  // after it (ms); 0 without.
  double drainedMs = 0.0;
  WorkCounts work;
};
struct WorkSteps {
  const WorkStep* steps = nullptr;
  int count = 0;
};
// The steps of the most recent resolved frame, in the order they ran: the shared passes'
// (TileIrradiance, LocalWater, ObjectCaustics, the lights) then the default view's for a
// context, a view's own (postfx/views.h) for a view. Empty without CreateDesc::workAccount.
// Valid until the next call on the context.
WorkSteps workSteps(const Context& context) noexcept;
WorkSteps workSteps(const View& view) noexcept;

// The message of the last failed call on `context`, or, for null, of the last failed create()
// on this thread: one sentence naming the field, its value and the accepted range or formats.
// Empty after success. Valid until the next call on the same context/thread.
const char* lastError(const Context* context) noexcept;

}  // namespace postfx
