#include "core/gpu_timers.h"

#include <algorithm>

namespace postfx::detail {

void GpuTimers::init(const std::array<bool, kPassCount>& present, int lights) {
  stats_ = FrameStats{};
  for (int p = 0; p < kPassCount; ++p) {
    stats_.passes[p].present = present[p];
    anyPass_ = anyPass_ || present[p];
  }
  for (int i = 0; i < lights && i < kMaxLocalLightsLimit; ++i) stats_.lights[i].present = true;
  for (auto& frame : queries_)
    for (int p = 0; p < kTimerCount; ++p) {
      if (!has(p)) continue;
      frame[p] = {glkit::createQuery(GL_TIMESTAMP), glkit::createQuery(GL_TIMESTAMP),
                  glkit::createQuery(GL_TIME_ELAPSED)};
    }
}

bool GpuTimers::tryResolve(Slot& slot, int slotIndex) {
  // All of a frame or none of it, so "last" always describes one frame.
  if (!work_.available(slotIndex)) return false;
  for (int p = 0; p < kTimerCount; ++p) {
    const bool elapsed = slot.state[p] == SlotState::IssuedElapsed;
    if (!elapsed && slot.state[p] != SlotState::IssuedTimestamps) continue;
    GLuint available = GL_FALSE;
    glGetQueryObjectuiv(queries_[slotIndex][p][elapsed ? 2 : 1].id(), GL_QUERY_RESULT_AVAILABLE,
                        &available);
    if (available != GL_TRUE) return false;
  }
  for (int p = 0; p < kTimerCount; ++p) {
    if (slot.state[p] == SlotState::IssuedElapsed) {
      GLuint64 ns = 0;
      glGetQueryObjectui64v(queries_[slotIndex][p][2].id(), GL_QUERY_RESULT, &ns);
      record(p, static_cast<double>(ns) * 1e-6, false);
    } else if (slot.state[p] == SlotState::IssuedTimestamps) {
      GLuint64 begin = 0, end = 0;
      // The end query is available, and queries complete in order, so these do not wait.
      glGetQueryObjectui64v(queries_[slotIndex][p][0].id(), GL_QUERY_RESULT, &begin);
      glGetQueryObjectui64v(queries_[slotIndex][p][1].id(), GL_QUERY_RESULT, &end);
      record(p, end > begin ? static_cast<double>(end - begin) * 1e-6 : 0.0, false);
    } else if (slot.state[p] == SlotState::Skipped) {
      record(p, 0.0, true);
    }
  }
  if (work_.enabled()) work_.resolve(slotIndex, stats_);
  ++stats_.framesResolved;
  return true;
}

void GpuTimers::record(int timer, double ms, bool skipped) {
  History& h = history_[timer];
  h.ms[h.next] = ms;
  h.next = (h.next + 1) % kTimerMedianWindow;
  h.count = std::min(h.count + 1, kTimerMedianWindow);
  std::array<double, kTimerMedianWindow> sorted = h.ms;
  std::sort(sorted.begin(), sorted.begin() + h.count);
  const double median = h.count % 2 == 1 ? sorted[h.count / 2]
                                         : 0.5 * (sorted[h.count / 2 - 1] + sorted[h.count / 2]);
  PassStats& s = timerStats(timer);
  s.lastMs = ms;
  s.medianMs = median;
  s.skipped = skipped;
  s.samples = static_cast<std::uint32_t>(h.count);
}

void GpuTimers::beginFrame() {
  if (!anyPass_) return;
  glBindBuffer(GL_QUERY_BUFFER, 0);
  while (oldest_ < frame_) {
    const int index = static_cast<int>(oldest_ % kTimerRingDepth);
    if (!tryResolve(slots_[index], index)) break;
    slots_[index].open = false;
    ++oldest_;
  }
  // The ring is full of pending frames: give up on the oldest rather than wait for it.
  if (frame_ - oldest_ >= static_cast<std::uint64_t>(kTimerRingDepth)) {
    slots_[oldest_ % kTimerRingDepth].open = false;
    work_.drop(static_cast<int>(oldest_ % kTimerRingDepth));
    ++oldest_;
    ++stats_.framesDropped;
  }
  Slot& slot = slots_[frame_ % kTimerRingDepth];
  slot.state.fill(SlotState::Empty);
  slot.open = true;
  work_.beginFrame(static_cast<int>(frame_ % kTimerRingDepth));
}

void GpuTimers::begin(Pass pass) {
  beginTimer(static_cast<int>(pass));
}

void GpuTimers::end(Pass pass) {
  endTimer(static_cast<int>(pass));
}

void GpuTimers::markSkipped(Pass pass) {
  markTimerSkipped(static_cast<int>(pass));
}

void GpuTimers::beginTimer(int timer) {
  if (!has(timer)) return;
  GLint hostQuery = 0;
  glGetQueryiv(GL_TIME_ELAPSED, GL_CURRENT_QUERY, &hostQuery);
  elapsedActive_ = hostQuery == 0;
  const auto& queries = queries_[frame_ % kTimerRingDepth][timer];
  if (elapsedActive_) {
    glBeginQuery(GL_TIME_ELAPSED, queries[2].id());
  } else {
    glQueryCounter(queries[0].id(), GL_TIMESTAMP);
  }
}

void GpuTimers::endTimer(int timer) {
  if (!has(timer)) return;
  const int index = static_cast<int>(frame_ % kTimerRingDepth);
  if (elapsedActive_) {
    glEndQuery(GL_TIME_ELAPSED);
    slots_[index].state[timer] = SlotState::IssuedElapsed;
  } else {
    glQueryCounter(queries_[index][timer][1].id(), GL_TIMESTAMP);
    slots_[index].state[timer] = SlotState::IssuedTimestamps;
  }
}

void GpuTimers::markTimerSkipped(int timer) {
  if (!has(timer)) return;
  slots_[frame_ % kTimerRingDepth].state[timer] = SlotState::Skipped;
}

void GpuTimers::endFrame() {
  if (!anyPass_) return;
  ++frame_;
  ++stats_.framesDispatched;
}

}  // namespace postfx::detail
