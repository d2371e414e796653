#include "core/work_account.h"

#include <algorithm>

#include "core/work_instrumentation.h"

namespace postfx {

WorkCounts& operator+=(WorkCounts& sum, const WorkCounts& w) noexcept {
  sum.draws += w.draws;
  sum.dispatches += w.dispatches;
  sum.clears += w.clears;
  sum.vertices += w.vertices;
  sum.primitivesSubmitted += w.primitivesSubmitted;
  sum.primitives += w.primitives;
  sum.fragments += w.fragments;
  sum.computeInvocations += w.computeInvocations;
  sum.samplesPassed += w.samplesPassed;
  sum.blendedSamples += w.blendedSamples;
  sum.fetches += w.fetches;
  sum.fragmentFetches += w.fragmentFetches;
  sum.atomics += w.atomics;
  sum.bytesRead += w.bytesRead;
  sum.bytesWritten += w.bytesWritten;
  sum.sources |= w.sources;
  return sum;
}

}  // namespace postfx

namespace postfx::detail {

// The scope the wrappers account into (null: no pass is being accounted).
struct ActiveWork {
  static thread_local WorkScope* scope;
  static WorkLedger* ledger() {
    return scope != nullptr && scope->ledger_->enabled() ? scope->ledger_ : nullptr;
  }
};
thread_local WorkScope* ActiveWork::scope = nullptr;

namespace {

// The queries of a step, in WorkLedger's query sets: the pipeline statistics, then samples.
constexpr GLenum kQueryTargets[] = {
    GL_VERTEX_SHADER_INVOCATIONS_ARB,   GL_CLIPPING_OUTPUT_PRIMITIVES_ARB,
    GL_FRAGMENT_SHADER_INVOCATIONS_ARB, GL_COMPUTE_SHADER_INVOCATIONS_ARB,
    GL_PRIMITIVES_SUBMITTED_ARB,        GL_SAMPLES_PASSED};
constexpr int kStatisticsQueries = 5;
constexpr int kSamplesQuery = 5;

std::uint64_t levelTexels(GLuint texture, GLint level) {
  GLint w = 0, h = 0, d = 0;
  glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_WIDTH, &w);
  glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_HEIGHT, &h);
  glGetTextureLevelParameteriv(texture, level, GL_TEXTURE_DEPTH, &d);
  return std::uint64_t(std::max(w, 0)) * std::uint64_t(std::max(h, 0)) *
         std::uint64_t(std::max(d, 0));
}

// Every level a texture has storage for (immutable: its levels; else until one is empty).
std::uint64_t allLevelsBytes(GLuint texture) {
  if (texture == 0) return 0;
  GLint target = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_TARGET, &target);
  if (target == GL_TEXTURE_BUFFER) {
    GLint size = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_BUFFER_SIZE, &size);
    return static_cast<std::uint64_t>(std::max(size, 0));
  }
  GLint levels = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  const std::uint64_t bytes = texelBytes(texture, 0);
  std::uint64_t texels = 0;
  for (GLint level = 0; level < (levels > 0 ? levels : 16); ++level) {
    const std::uint64_t n = levelTexels(texture, level);
    if (n == 0) break;
    texels += n;
  }
  return texels * bytes;
}

std::uint64_t trafficBytes(const Traffic& t) {
  switch (t.kind) {
    case Traffic::Kind::Texture:
      return allLevelsBytes(t.name);
    case Traffic::Kind::TextureLevel0:
      return t.name == 0 ? 0
                         : static_cast<std::uint64_t>(
                               t.share * double(levelTexels(t.name, 0) * texelBytes(t.name, 0)));
    case Traffic::Kind::Buffer: {
      if (t.name == 0) return 0;
      GLint64 size = 0;
      glGetNamedBufferParameteri64v(t.name, GL_BUFFER_SIZE, &size);
      return static_cast<std::uint64_t>(t.share * double(std::max<GLint64>(size, 0)));
    }
    case Traffic::Kind::Bytes:
      return t.bytes;
  }
  return 0;
}

// The bound draw framebuffer's colour attachments that a draw writes (bytes per sample, and
// whether any is blended), and its depth attachment's when the depth test is on.
void renderTargets(int& colorBytes, int& depthBytes, bool& blended) {
  colorBytes = depthBytes = 0;
  blended = false;
  GLint fbo = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &fbo);
  if (fbo == 0) return;
  GLint maxDrawBuffers = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &maxDrawBuffers);
  for (GLint i = 0; i < std::min(maxDrawBuffers, 8); ++i) {
    GLint buffer = GL_NONE;
    glGetIntegerv(static_cast<GLenum>(GL_DRAW_BUFFER0 + i), &buffer);
    if (buffer == GL_NONE) continue;
    GLint type = GL_NONE, name = 0, level = 0;
    glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(fbo),
                                               static_cast<GLenum>(buffer),
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) continue;
    glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(fbo),
                                               static_cast<GLenum>(buffer),
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(fbo),
                                               static_cast<GLenum>(buffer),
                                               GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
    colorBytes += static_cast<int>(texelBytes(static_cast<GLuint>(name), level));
    blended = blended || glIsEnabledi(GL_BLEND, static_cast<GLuint>(i)) == GL_TRUE;
  }
  if (glIsEnabled(GL_DEPTH_TEST) == GL_TRUE) {
    GLint type = GL_NONE, name = 0;
    glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(fbo), GL_DEPTH_ATTACHMENT,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type == GL_TEXTURE) {
      glGetNamedFramebufferAttachmentParameteriv(static_cast<GLuint>(fbo), GL_DEPTH_ATTACHMENT,
                                                 GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
      depthBytes = static_cast<int>(texelBytes(static_cast<GLuint>(name), 0));
    }
  }
}

std::uint64_t times(double perInvocation, std::uint64_t invocations) {
  return static_cast<std::uint64_t>(perInvocation * double(invocations) + 0.5);
}

}  // namespace

std::uint64_t texelBytes(GLuint texture, GLint level) {
  if (texture == 0) return 0;
  constexpr GLenum kSizes[] = {
      GL_TEXTURE_RED_SIZE,   GL_TEXTURE_GREEN_SIZE,   GL_TEXTURE_BLUE_SIZE,  GL_TEXTURE_ALPHA_SIZE,
      GL_TEXTURE_DEPTH_SIZE, GL_TEXTURE_STENCIL_SIZE, GL_TEXTURE_SHARED_SIZE};
  GLint bits = 0;
  for (GLenum size : kSizes) {
    GLint b = 0;
    glGetTextureLevelParameteriv(texture, level, size, &b);
    bits += std::max(b, 0);
  }
  return static_cast<std::uint64_t>((bits + 7) / 8);
}

void WorkLedger::init(bool enabled, bool counted, bool drained) {
  enabled_ = enabled;
  counted_ = enabled && counted;
  drained_ = enabled && drained;
  statistics_ =
      epoxy_gl_version() >= 46 || epoxy_has_gl_extension("GL_ARB_pipeline_statistics_query");
  if (counted_) {
    counters_ = glkit::createBuffer(kWorkCounterBytes, nullptr, GL_DYNAMIC_STORAGE_BIT,
                                    "postfx.work_counters");
  }
}

void WorkLedger::beginFrame(int slot) {
  slot_ = slot;
  Frame& f = frames_[static_cast<std::size_t>(slot)];
  f.steps.clear();
  f.used = 0;
}

bool WorkLedger::available(int slot) const {
  const Frame& f = frames_[static_cast<std::size_t>(slot)];
  for (const Record& r : f.steps) {
    if (r.queries < 0) continue;
    for (int q = 0; q < kQueriesPerStep; ++q) {
      if ((r.missing >> q) & 1u) continue;
      GLuint ready = GL_FALSE;
      glGetQueryObjectuiv(f.queries[static_cast<std::size_t>(r.queries)][q].id(),
                          GL_QUERY_RESULT_AVAILABLE, &ready);
      if (ready != GL_TRUE) return false;
    }
  }
  return true;
}

WorkLedger::Record& WorkLedger::open(const Step& step, Pass pass, int light) {
  Frame& f = frames_[static_cast<std::size_t>(slot_)];
  Record& r = f.steps.emplace_back();
  r.step.name = step.name;
  r.step.pass = pass;
  r.step.light = light;
  r.vertex = step.vertex;
  r.shading = step.shading;
  for (const Traffic& t : step.traffic)
    (t.writes ? r.step.work.bytesWritten : r.step.work.bytesRead) += trafficBytes(t);
  if (f.used == static_cast<int>(f.queries.size())) {
    auto& set = f.queries.emplace_back();
    // Named only: glBeginQuery makes each (Mesa 22's glCreateQueries refuses the statistics).
    for (int q = 0; q < kQueriesPerStep; ++q) set[q] = glkit::genQuery();
  }
  r.queries = f.used++;
  const auto& set = f.queries[static_cast<std::size_t>(r.queries)];
  for (int q = 0; q < kQueriesPerStep; ++q) {
    GLint hostQuery = 0;
    if (drained_ || (q < kStatisticsQueries && !statistics_)) {
      r.missing |= 1u << q;
      continue;
    }
    glGetQueryiv(kQueryTargets[q], GL_CURRENT_QUERY, &hostQuery);
    if (hostQuery != 0) {
      r.missing |= 1u << q;  // the host's own query of this kind is active: it keeps the target
      continue;
    }
    glBeginQuery(kQueryTargets[q], set[q].id());
  }
  if (counted_) {
    glClearNamedBufferData(counters_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kWorkCounterBinding, counters_.id());
  }
  if (drained_) {  // a testing hook: the GPU drained, the step's own time taken from here
    glFinish();
    r.start = std::chrono::steady_clock::now();
  }
  return r;
}

void WorkLedger::close(Record& r) {
  if (drained_) {
    glFinish();
    r.step.drainedMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - r.start)
            .count();
  }
  for (int q = 0; q < kQueriesPerStep; ++q)
    if (!((r.missing >> q) & 1u)) glEndQuery(kQueryTargets[q]);
  if (counted_) {
    // A testing hook: the counters are read at once (this waits for the step).
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    std::uint32_t c[kWorkCounterCount] = {};
    glGetNamedBufferSubData(counters_.id(), 0, sizeof(c), c);
    r.counted = true;
    for (int i = 0; i < kWorkCounterCount; ++i) r.counts[i] = c[i];
  }
}

void WorkLedger::addClear(const char* name, Pass pass, int light, std::uint64_t bytes) {
  Record& r = frames_[static_cast<std::size_t>(slot_)].steps.emplace_back();
  r.step.name = name;
  r.step.pass = pass;
  r.step.light = light;
  r.step.work.clears = 1;
  r.step.work.bytesWritten = bytes;
}

void WorkLedger::resolve(int slot, FrameStats& stats) {
  Frame& f = frames_[static_cast<std::size_t>(slot)];
  resolved_.clear();
  for (PassStats& p : stats.passes) p.work = {};
  for (PassStats& p : stats.lights) p.work = {};
  for (Record& r : f.steps) {
    WorkCounts& w = r.step.work;
    if (r.queries >= 0) {
      const auto& set = f.queries[static_cast<std::size_t>(r.queries)];
      GLuint64 value[kQueriesPerStep] = {};
      for (int q = 0; q < kQueriesPerStep; ++q)
        if (!((r.missing >> q) & 1u))
          glGetQueryObjectui64v(set[q].id(), GL_QUERY_RESULT, &value[q]);
      const bool statistics = (r.missing & ((1u << kStatisticsQueries) - 1)) == 0;
      if (statistics) {
        w.vertices = value[0];
        w.primitives = value[1];
        w.fragments = value[2];
        w.computeInvocations = value[3];
        w.primitivesSubmitted = value[4];
        w.sources |= kWorkFromPipelineStatistics;
      } else {
        w.vertices = r.drawVertices;
        w.computeInvocations = r.dispatchInvocations;
      }
      if (!((r.missing >> kSamplesQuery) & 1u)) {
        w.samplesPassed = value[kSamplesQuery];
        w.blendedSamples = r.step.blended ? w.samplesPassed : 0;
        w.sources |= kWorkFromSamplesPassed;
      }
      // Render targets: written per sample, read too when blended; depth read and written.
      w.bytesWritten += w.samplesPassed * std::uint64_t(r.step.targetBytes + r.depthBytes);
      w.bytesRead += w.blendedSamples * std::uint64_t(r.step.targetBytes) +
                     w.samplesPassed * std::uint64_t(r.depthBytes);
      if (r.counted) {
        auto count = [&r](int stage, int k) { return std::uint64_t(r.counts[3 * stage + k]); };
        w.vertices = count(kWorkVertexStage, kWorkInvocations);
        w.fragments = count(kWorkFragmentStage, kWorkInvocations);
        w.computeInvocations = count(kWorkComputeStage, kWorkInvocations);
        w.fragmentFetches = count(kWorkFragmentStage, kWorkFetches);
        w.fetches = count(kWorkVertexStage, kWorkFetches) + w.fragmentFetches +
                    count(kWorkComputeStage, kWorkFetches);
        w.atomics = count(kWorkVertexStage, kWorkAtomics) +
                    count(kWorkFragmentStage, kWorkAtomics) +
                    count(kWorkComputeStage, kWorkAtomics);
        w.sources |= kWorkCounted;
      }
      // The shaders' stated work per invocation, for the invocations above.
      const std::uint64_t shading = w.fragments + w.computeInvocations;
      r.step.statedFetches =
          times(r.vertex.fetches, w.vertices) + times(r.shading.fetches, shading);
      r.step.statedAtomics =
          times(r.vertex.atomics, w.vertices) + times(r.shading.atomics, shading);
      r.step.statedBound = r.vertex.bound || r.shading.bound;
      if (!r.counted) {
        w.fragmentFetches = times(r.shading.fetches, w.fragments);
        w.fetches = r.step.statedFetches;
        w.atomics = r.step.statedAtomics;
      }
    }
    resolved_.push_back(r.step);
    PassStats& sums = r.step.light >= 0 && r.step.light < kMaxLocalLightsLimit
                          ? stats.lights[r.step.light]
                          : stats.passes[static_cast<int>(r.step.pass)];
    sums.work += w;
  }
  f.steps.clear();
}

WorkScope::WorkScope(WorkLedger& ledger, Pass pass, int light)
    : previous_(ActiveWork::scope), ledger_(&ledger), pass_(pass), light_(light) {
  ActiveWork::scope = this;
}

WorkScope::~WorkScope() {
  ActiveWork::scope = previous_;
}

namespace {

// Opens a step for a draw (its render targets looked up) or a dispatch, or null.
WorkLedger::Record* openStep(const Step& step, bool draw) {
  WorkLedger* ledger = ActiveWork::ledger();
  if (ledger == nullptr) return nullptr;
  const WorkScope& scope = *ActiveWork::scope;
  WorkLedger::Record& r = ledger->open(step, scope.pass(), scope.light());
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  r.step.program = static_cast<GlName>(program);
  if (draw) {
    r.step.work.draws = 1;
    GLint viewport[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, viewport);
    r.step.viewportPixels = std::uint64_t(std::max(viewport[2], 0)) * std::max(viewport[3], 0);
    renderTargets(r.step.targetBytes, r.depthBytes, r.step.blended);
  } else {
    r.step.work.dispatches = 1;
  }
  return &r;
}

}  // namespace

namespace work {

void drawArrays(const Step& step, GLenum mode, GLint first, GLsizei count, GLsizei instances) {
  WorkLedger::Record* r = openStep(step, true);
  if (instances == 1)
    glDrawArrays(mode, first, count);
  else
    glDrawArraysInstanced(mode, first, count, instances);
  if (r == nullptr) return;
  r->drawVertices = std::uint64_t(count) * std::uint64_t(instances);
  ActiveWork::ledger()->close(*r);
}

void drawElements(const Step& step, GLenum mode, GLsizei count, GLenum type, const void* indices) {
  WorkLedger::Record* r = openStep(step, true);
  glDrawElements(mode, count, type, indices);
  if (r == nullptr) return;
  r->drawVertices = std::uint64_t(count);
  ActiveWork::ledger()->close(*r);
}

void dispatchCompute(const Step& step, GLuint x, GLuint y, GLuint z) {
  WorkLedger::Record* r = openStep(step, false);
  glDispatchCompute(x, y, z);
  if (r == nullptr) return;
  GLint size[3] = {0, 0, 0};
  if (r->step.program != 0) glGetProgramiv(r->step.program, GL_COMPUTE_WORK_GROUP_SIZE, size);
  r->dispatchInvocations = std::uint64_t(x) * y * z * std::uint64_t(size[0]) * size[1] * size[2];
  ActiveWork::ledger()->close(*r);
}

void noteClear(const char* name, std::uint64_t bytes) {
  WorkLedger* ledger = ActiveWork::ledger();
  if (ledger == nullptr) return;
  ledger->addClear(name, ActiveWork::scope->pass(), ActiveWork::scope->light(), bytes);
}

}  // namespace work

}  // namespace postfx::detail
