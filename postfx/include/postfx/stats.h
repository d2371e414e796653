#pragma once
// Per-pass GPU timings, read from timestamp queries without ever waiting on the GPU: a pass's
// numbers describe a frame a few dispatches old (the ring is kTimerRingDepth frames deep).
#include <cstdint>

namespace postfx {

inline constexpr int kTimerRingDepth = 4;      // frames of timestamp pairs in flight
inline constexpr int kTimerMedianWindow = 64;  // resolved frames the median is taken over
inline constexpr int kMaxPasses = 6;

struct PassStats {
  const char* name = "";      // "caustics", "floor" (BenchmarkFloor only), "god_rays",
                              // "caustics_irradiance" (PhysicalCaustics only)
                              // "object_caustics", "caustics_tile_irradiance"
                              // (Feature::Caustics: TileIrradiance's pre-pass)
  double lastMs = 0.0;        // GPU time of the most recent resolved frame; 0 when skipped
  double medianMs = 0.0;      // median over the last kTimerMedianWindow resolved frames
  bool skipped = false;       // the most recent resolved frame skipped this pass (nothing to do)
  std::uint32_t samples = 0;  // resolved frames in the median window (skipped ones count as 0 ms)
};

struct FrameStats {
  PassStats passes[kMaxPasses];
  int passCount = 0;
  std::uint64_t framesDispatched = 0;  // successful dispatch() calls
  std::uint64_t framesResolved = 0;    // of those, frames whose timings have been read back
  std::uint64_t framesDropped = 0;     // frames whose queries were still pending when the ring
                                       // wrapped (read never, rather than stall)
  // CausticsModel::WavefrontAreaRatio: the flux CausticsSettings::maxIrradiance removed in the
  // most recent frame whose count has been read back (a few dispatches old, never stalled
  // for), as a fraction of the window's flat-water flux summed over the depth layers. 0 in
  // the RayDeviation model; -1 until a first count is read.
  double clampedFluxFraction = -1.0;
};

}  // namespace postfx
