#pragma once
// The work account (CreateDesc::workAccount, postfx/diagnostics.h): every draw, dispatch and
// clear the passes record goes through the wrappers below, which issue exactly the GL call and,
// while a frame is being accounted, count it: pipeline-statistics and samples-passed queries
// around it (read back with the timers, never waited for), its draw or dispatch size, the bytes
// of what it reads and writes, and each shader's stated work per invocation (docs/gpu_cost.md).
// With testing::CountShaderWork the shaders count their own invocations, fetches and atomics
// (work_instrumentation.h) and the wrapper reads them back at once (a testing hook: it waits).
#include <epoxy/gl.h>

#include <array>
#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <vector>

#include <glkit/handle.h>
#include <postfx/diagnostics.h>

namespace postfx::detail {

// What one shader stage does per invocation on its full path (the path an underwater pixel, or
// a ray that reaches every step, takes): stated beside each pass's draw, held to the counted
// numbers by a test.
struct StageWork {
  double fetches = 0.0;  // texture and image reads
  double atomics = 0.0;  // atomic operations
  // The counts are a bound, not the path: a data-dependent loop (a march, a blur whose radius
  // the data sets) stated at its longest.
  bool bound = false;
};

// Memory a step reads or writes at least once, besides its render targets (found from the GL
// state at the draw): a texture (every level), the share of one (a view's rectangle of the
// host's G-buffer), a buffer, or bytes the pass computed itself.
struct Traffic {
  enum class Kind : std::uint8_t { Texture, TextureLevel0, Buffer, Bytes };
  Kind kind = Kind::Bytes;
  bool writes = false;
  GLuint name = 0;
  double share = 1.0;       // of the texture or buffer
  std::uint64_t bytes = 0;  // Kind::Bytes

  static Traffic read(GLuint texture) { return {Kind::Texture, false, texture}; }
  static Traffic write(GLuint texture) { return {Kind::Texture, true, texture}; }
  // Level 0 only, `share` of it: a rectangle of a host texture.
  static Traffic readLevel0(GLuint texture, double share = 1.0) {
    return {Kind::TextureLevel0, false, texture, share};
  }
  static Traffic readBuffer(GLuint buffer, double share = 1.0) {
    return {Kind::Buffer, false, buffer, share};
  }
  static Traffic writeBuffer(GLuint buffer, double share = 1.0) {
    return {Kind::Buffer, true, buffer, share};
  }
  static Traffic readBytes(std::uint64_t n) { return {Kind::Bytes, false, 0, 1.0, n}; }
  static Traffic writeBytes(std::uint64_t n) { return {Kind::Bytes, true, 0, 1.0, n}; }
};

// What a step reads and writes: a few entries, kept by value.
class TrafficList {
 public:
  TrafficList() = default;
  TrafficList(std::initializer_list<Traffic> list) {
    for (const Traffic& t : list) add(t);
  }
  void add(const Traffic& t) {
    if (count_ < static_cast<int>(items_.size())) items_[static_cast<std::size_t>(count_++)] = t;
  }
  const Traffic* begin() const { return items_.data(); }
  const Traffic* end() const { return items_.data() + count_; }

 private:
  std::array<Traffic, 12> items_{};
  int count_ = 0;
};

// One step of a pass: its stable name ("<pass>.<step>"), what its stages do per invocation
// (`shading`: the fragment or the compute stage) and what it reads and writes.
struct Step {
  const char* name;
  StageWork vertex{};
  StageWork shading{};
  TrafficList traffic{};
};

// A dispatch's work per invocation when `items` of its `invocations` do `perItem` each and the
// rest (the last groups' padding) return at once.
inline double perInvocation(double perItem, double items, double invocations) {
  return invocations > 0.0 ? perItem * items / invocations : 0.0;
}

namespace work {
// The GL calls, accounted while a frame is (exactly the GL call otherwise).
void drawArrays(const Step& step, GLenum mode, GLint first, GLsizei count, GLsizei instances = 1);
void drawElements(const Step& step, GLenum mode, GLsizei count, GLenum type, const void* indices);
void dispatchCompute(const Step& step, GLuint x, GLuint y, GLuint z);
// A clear (or copy) the pass has just made, of `bytes`.
void noteClear(const char* name, std::uint64_t bytes);
}  // namespace work

// Bytes per texel of a texture's level, from its components' sizes (GL_TEXTURE_*_SIZE).
std::uint64_t texelBytes(GLuint texture, GLint level = 0);

// The SSBO binding the counting shaders write their counters to (work_instrumentation.h).
inline constexpr GLuint kWorkCounterBinding = 3;

// The account of one set of timers (a view's, or the context's shared passes'): per frame of
// the timers' ring, the steps recorded and their queries.
class WorkLedger {
 public:
  // `counted`: the context's programs count their own work (testing::CountShaderWork);
  // `drained`: each step is timed alone (testing::TimeEachStep).
  void init(bool enabled, bool counted, bool drained);
  bool enabled() const { return enabled_; }

  void beginFrame(int slot);
  // Whether every query of a slot's frame has its result (a ledger that is off: always).
  bool available(int slot) const;
  // Reads a slot's frame into steps() and the per-pass sums of `stats`.
  void resolve(int slot, FrameStats& stats);
  void drop(int slot) { frames_[static_cast<std::size_t>(slot)].steps.clear(); }

  const std::vector<WorkStep>& steps() const { return resolved_; }

  // Used by the wrappers through the active scope.
  struct Record {
    WorkStep step;
    StageWork vertex, shading;  // stated per invocation
    int depthBytes = 0;         // depth attachment, when the depth test is on
    std::uint64_t drawVertices = 0, dispatchInvocations = 0;  // from the call's sizes
    int queries = -1;           // index into the frame's query sets, -1 for a clear
    std::uint32_t missing = 0;  // queries not issued (no pipeline statistics, or the host's)
    bool counted = false;       // counts[] read from the shaders' own counters
    std::chrono::steady_clock::time_point start;  // testing::TimeEachStep
    std::uint32_t counts[9] = {};
  };
  Record& open(const Step& step, Pass pass, int light);
  void close(Record& record);
  void addClear(const char* name, Pass pass, int light, std::uint64_t bytes);

 private:
  static constexpr int kQueriesPerStep = 6;
  struct Frame {
    std::vector<Record> steps;
    std::vector<std::array<glkit::Query, kQueriesPerStep>> queries;  // grows, reused
    int used = 0;
  };
  bool enabled_ = false, counted_ = false, drained_ = false, statistics_ = false;
  int slot_ = 0;
  std::array<Frame, kTimerRingDepth> frames_{};
  std::vector<WorkStep> resolved_;
  glkit::Buffer counters_;  // testing::CountShaderWork: the shaders' counters
};

// Where the wrappers account while a timed pass records (the timers' ledger, the pass, the local
// light); restores the previous scope when it ends.
class WorkScope {
 public:
  WorkScope(WorkLedger& ledger, Pass pass, int light = -1);
  ~WorkScope();
  WorkScope(const WorkScope&) = delete;
  WorkScope& operator=(const WorkScope&) = delete;
  Pass pass() const { return pass_; }
  int light() const { return light_; }

 private:
  WorkScope* previous_;
  WorkLedger* ledger_;
  Pass pass_;
  int light_;
  friend struct ActiveWork;
};

}  // namespace postfx::detail
