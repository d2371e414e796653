#include "water_bench.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <iomanip>
#include <memory>
#include <string>
#include <vector>

#include <postfx/water/ocean.h>

namespace {

// Deep enough that the oldest pair has finished by the time its slot comes round again, so
// reading it never stalls the pipeline (DESIGN.md: at least 3 frames).
constexpr int kRingDepth = 4;
constexpr int kWarmupFrames = 3;  // first updates pay shader JIT and first-touch page faults

struct TimerRing {
  std::array<GLuint, 2 * kRingDepth> queries{};
  std::array<bool, kRingDepth> pending{};
  TimerRing() { glCreateQueries(GL_TIMESTAMP, 2 * kRingDepth, queries.data()); }
  ~TimerRing() { glDeleteQueries(2 * kRingDepth, queries.data()); }
  TimerRing(const TimerRing&) = delete;
  TimerRing& operator=(const TimerRing&) = delete;

  // Milliseconds between the pair in `slot`. Blocks only if the GPU is kRingDepth frames
  // behind, which is then the honest cost anyway.
  double read(int slot) {
    GLuint64 begin = 0, end = 0;
    glGetQueryObjectui64v(queries[2 * slot], GL_QUERY_RESULT, &begin);
    glGetQueryObjectui64v(queries[2 * slot + 1], GL_QUERY_RESULT, &end);
    pending[slot] = false;
    return static_cast<double>(end - begin) * 1e-6;
  }
};

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  std::sort(values.begin(), values.end());
  const size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

struct Row {
  int resolution;
  int cascades;
  double medianMs, minMs;
  size_t bytes;
};

bool measure(int resolution, int frames, Row& row, std::string& error) {
  postfx::water::OceanDesc desc;
  desc.resolution = resolution;
  std::unique_ptr<postfx::water::Ocean> ocean;
  if (postfx::water::Ocean::create(desc, ocean, error) != postfx::water::Result::Ok) return false;
  TimerRing ring;
  std::vector<double> samples;
  const int total = kWarmupFrames + std::max(frames, 5);
  auto collect = [&](int frame) {
    const int slot = frame % kRingDepth;
    if (!ring.pending[slot]) return;
    const double ms = ring.read(slot);
    if (frame >= kWarmupFrames) samples.push_back(ms);
  };
  for (int frame = 0; frame < total; ++frame) {
    const int slot = frame % kRingDepth;
    if (frame >= kRingDepth) collect(frame - kRingDepth);
    glQueryCounter(ring.queries[2 * slot], GL_TIMESTAMP);
    // 1/60 s steps from far in the future: the cost must not depend on the time value.
    if (ocean->update(1e6 + frame / 60.0, error) != postfx::water::Result::Ok) return false;
    glQueryCounter(ring.queries[2 * slot + 1], GL_TIMESTAMP);
    ring.pending[slot] = true;
  }
  for (int frame = std::max(0, total - kRingDepth); frame < total; ++frame) collect(frame);
  row = {resolution, desc.cascadeCount, median(samples),
         samples.empty() ? 0.0 : *std::min_element(samples.begin(), samples.end()),
         ocean->gpuBytes()};
  return true;
}

}  // namespace

int runWaterBench(std::ostream& out, int frames) {
  std::vector<Row> rows;
  for (int resolution : {64, 128, 256, 512}) {
    Row row{};
    std::string error;
    if (!measure(resolution, frames, row, error)) {
      out << "water bench: N = " << resolution << ": " << error << "\n";
      return 1;
    }
    rows.push_back(row);
  }
  out << "   N  cascades  GPU ms (median)  GPU ms (min)  GPU memory MiB\n";
  for (const Row& row : rows) {
    out << std::setw(4) << row.resolution << std::setw(10) << row.cascades << std::fixed
        << std::setprecision(3) << std::setw(17) << row.medianMs << std::setw(14) << row.minMs
        << std::setprecision(2) << std::setw(16)
        << static_cast<double>(row.bytes) / (1024.0 * 1024.0) << "\n";
  }
  out << "(" << std::max(frames, 5) << " timed frames after " << kWarmupFrames
      << " warm-up, GL_TIMESTAMP pairs in a " << kRingDepth << "-deep ring)\n";
  return 0;
}
