#include "pass_runner.h"
#include <postfx/testing.h>

#include <gpu_cost.h>
#include <object_caustics_metrics.h>
#include <shader_statistics.h>

#include <memory>

namespace ocean::validation {
namespace {

constexpr int kWarmupFrames = 4;
bool estimating = false;

// PassRun::estimatedMs: `frame` counted once in a context of its own.
void estimateRun(postfx::CreateDesc create, const postfx::FrameDesc& frame,
                 postfx::testing::GodRaySampling sampling,
                 const std::map<std::string, cost::ProgramStatistics>& programs, double viewPixels,
                 PassRun& out) {
  out.estimatedMs.fill(0.0);
  std::vector<cost::GpuClass> gpus;
  std::string error;
  if (!cost::selectGpuClasses("rtx3060", gpus, error)) return;
  create.features = create.features | postfx::testing::CountShaderWork;
  create.workAccount = true;
  postfx::Context* context = nullptr;
  if (postfx::create(create, context) != postfx::Result::Ok) return;
  postfx::testing::setGodRaySampling(*context, sampling);
  bool ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
  glFinish();
  ok = ok && postfx::dispatch(*context, frame) == postfx::Result::Ok;
  const postfx::WorkSteps steps = postfx::workSteps(*context);
  if (ok)
    out.estimatedMs = cost::passEstimatesMs(steps, programs, gpus[0], viewPixels, 1920.0 * 1080.0);
  out.hasEstimate = ok && steps.count > 0;
  postfx::destroy(context);
}

}  // namespace

void estimateRuns(bool on) {
  estimating = on;
}

bool estimatingRuns() {
  return estimating;
}

ReportTarget::ReportTarget(int width, int height)
    : texture_(glkit::createTexture(GL_TEXTURE_2D, {})), width_(width), height_(height) {
  glTextureStorage2D(texture_.id(), 1, GL_RGBA32F, width, height);
}

bool runPass(postfx::CreateDesc create, postfx::FrameDesc frame, postfx::Pass pass,
             const ReportTarget& target, int timedFrames, PassRun& out, std::string& error,
             postfx::testing::GodRaySampling sampling) {
  create.features = create.features | postfx::testing::BenchmarkFloor;
  // Mesa's dump of the programs this context builds (where the caller asked for it): the
  // arithmetic of the estimate.
  auto dump = estimating ? std::make_unique<cost::ShaderDumpCapture>() : nullptr;
  postfx::Context* context = nullptr;
  if (postfx::create(create, context) != postfx::Result::Ok) {
    dump.reset();
    error = std::string("postfx: ") + postfx::lastError(nullptr);
    return false;
  }
  postfx::testing::setGodRaySampling(*context, sampling);
  frame.target = {target.texture(), GL_RGBA32F};
  const float zero[4] = {0.0f, 0.0f, 0.0f, 0.0f};
  bool ok = true;
  // The timers never stall, so a frame's numbers arrive a few dispatches later: run the ring's
  // depth more, and finish each frame so the queries time this pass alone.
  const int total = kWarmupFrames + timedFrames + postfx::kTimerRingDepth;
  for (int i = 0; i < total && ok; ++i) {
    ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
    glFinish();
  }
  const std::map<std::string, cost::ProgramStatistics> programs =
      dump ? cost::labelled(cost::parseNirDump(dump->text()))
           : std::map<std::string, cost::ProgramStatistics>{};
  dump.reset();
  if (ok) {
    const postfx::FrameStats& stats = postfx::stats(*context);
    out.medianMs = stats.pass(pass).medianMs;
    out.floorMs = stats.pass(postfx::Pass::Floor).medianMs;
    out.stats = stats;
    glClearTexImage(target.texture(), 0, GL_RGBA, GL_FLOAT, zero);
    ok = postfx::dispatch(*context, frame) == postfx::Result::Ok;
  }
  if (!ok) {
    error = std::string("postfx: ") + postfx::lastError(context);
  } else {
    const size_t pixels = size_t(target.width()) * size_t(target.height());
    out.image.resize(pixels);
    glGetTextureImage(target.texture(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels * sizeof(glm::vec4)),
                      out.image.data());
    out.raw.clear();
    if (const GLuint raw = postfx::testing::rawCausticTexture(*context)) {
      out.raw.resize(pixels);
      glGetTextureImage(raw, 0, GL_RED, GL_FLOAT, GLsizei(pixels * sizeof(float)), out.raw.data());
    }
    out.objectMapPlacement = postfx::objectCausticMap(*context);
    out.objectMap.clear();
    if (out.objectMapPlacement.texture != 0)
      out.objectMap = ocean::reference::readObjectMap(out.objectMapPlacement);
  }
  postfx::destroy(context);
  if (ok && estimating)
    estimateRun(create, frame, sampling, programs, double(target.width()) * double(target.height()),
                out);
  return ok;
}

}  // namespace ocean::validation
