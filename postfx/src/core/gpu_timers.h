#pragma once
// Per-pass GPU timing in a ring of kTimerRingDepth frames. Results are read oldest-first and
// only once GL_QUERY_RESULT_AVAILABLE says so: the CPU never waits. When the ring wraps onto a
// frame still pending, that frame is dropped instead (counted).
// Each pass is timed by a GL_TIME_ELAPSED query when the host has none active, else by a
// GL_TIMESTAMP pair (elapsed queries cannot nest inside the host's). Why not timestamps only:
// llvmpipe executes a timestamp once per tile and keeps the latest, so a pair measures one
// tile, not the pass; an elapsed query spans first to last tile. On GPUs both are exact.
#include <epoxy/gl.h>

#include <array>
#include <cstdint>

#include <glkit/handle.h>
#include <postfx/diagnostics.h>

#include "core/work_account.h"

namespace postfx::detail {

class GpuTimers {
 public:
  // Creates the query objects of the passes the context has, and of its first `lights` local
  // lights (DSA, no binding changes).
  void init(const std::array<bool, kPassCount>& present, int lights = 0);
  // The work account of these timers' passes (CreateDesc::workAccount), read back with them.
  void initWork(bool enabled, bool counted, bool drained) { work_.init(enabled, counted, drained); }
  WorkLedger& work() { return work_; }
  const WorkLedger& work() const { return work_; }

  // Reads every completed frame in order, then opens a slot for this frame. Binds
  // GL_QUERY_BUFFER to 0 while reading (so results land in client memory): call under a guard.
  void beginFrame();
  // A pass the context does not have is ignored by all three.
  void begin(Pass pass);        // timestamp before the pass's GL work
  void end(Pass pass);          // timestamp after it
  void markSkipped(Pass pass);  // the pass had nothing to do this frame: it resolves to 0 ms
  // The same for local light i's object caustics (FrameStats::lights).
  void beginLight(int light) { beginTimer(kPassCount + light); }
  void endLight(int light) { endTimer(kPassCount + light); }
  void markLightSkipped(int light) { markTimerSkipped(kPassCount + light); }
  void setLightSkip(int light, LightSkip skip) { stats_.lightSkip[light] = skip; }
  void endFrame();

  const FrameStats& stats() const { return stats_; }
  // Not a timing, but read back on the same never-stall terms: see FrameStats.
  void setClampedFluxFraction(double fraction) { stats_.clampedFluxFraction = fraction; }

 private:
  // The passes, then the local lights.
  static constexpr int kTimerCount = kPassCount + kMaxLocalLightsLimit;
  enum class SlotState : std::uint8_t { Empty, IssuedTimestamps, IssuedElapsed, Skipped };
  struct Slot {
    std::array<SlotState, kTimerCount> state{};
    bool open = false;  // frame dispatched, timings not yet read
  };
  struct History {
    std::array<double, kTimerMedianWindow> ms{};
    int count = 0, next = 0;
  };

  bool tryResolve(Slot& slot, int slotIndex);
  void record(int timer, double ms, bool skipped);
  void beginTimer(int timer);
  void endTimer(int timer);
  void markTimerSkipped(int timer);
  PassStats& timerStats(int timer) {
    return timer < kPassCount ? stats_.passes[timer] : stats_.lights[timer - kPassCount];
  }
  bool has(int timer) { return timerStats(timer).present; }

  bool anyPass_ = false;
  // Per frame and timer: timestamp begin, timestamp end, time elapsed.
  std::array<std::array<std::array<glkit::Query, 3>, kTimerCount>, kTimerRingDepth> queries_{};
  bool elapsedActive_ = false;
  std::array<Slot, kTimerRingDepth> slots_{};
  std::array<History, kTimerCount> history_{};
  WorkLedger work_;
  std::uint64_t frame_ = 0;   // frames begun
  std::uint64_t oldest_ = 0;  // oldest frame not yet resolved or dropped
  FrameStats stats_;
};

}  // namespace postfx::detail
