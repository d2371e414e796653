#pragma once
// What the plugin reports back: per-pass GPU timings (read from timestamp queries without ever
// waiting on the GPU: a pass's numbers describe a frame a few dispatches old, the ring is
// kTimerRingDepth frames deep) and the message of the last failed call.
#include <cstdint>

#include <postfx/lights.h>

namespace postfx {

struct Context;

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

struct PassStats {
  bool present = false;       // the context has this pass (its feature was given at create())
  double lastMs = 0.0;        // GPU time of the most recent resolved frame; 0 when skipped
  double medianMs = 0.0;      // median over the last kTimerMedianWindow resolved frames
  bool skipped = false;       // the most recent resolved frame skipped this pass (nothing to do)
  std::uint32_t samples = 0;  // resolved frames in the median window (skipped ones count as 0 ms)
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

// The message of the last failed call on `context`, or, for null, of the last failed create()
// on this thread: one sentence naming the field, its value and the accepted range or formats.
// Empty after success. Valid until the next call on the same context/thread.
const char* lastError(const Context* context) noexcept;

}  // namespace postfx
