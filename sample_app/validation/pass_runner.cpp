#include "pass_runner.h"
#include <postfx/testing.h>

#include <object_caustics_metrics.h>

namespace ocean::validation {
namespace {

constexpr int kWarmupFrames = 4;

}  // namespace

ReportTarget::ReportTarget(int width, int height)
    : texture_(glkit::createTexture(GL_TEXTURE_2D, {})), width_(width), height_(height) {
  glTextureStorage2D(texture_.id(), 1, GL_RGBA32F, width, height);
}

bool runPass(postfx::CreateDesc create, postfx::FrameDesc frame, postfx::Pass pass,
             const ReportTarget& target, int timedFrames, PassRun& out, std::string& error,
             postfx::testing::GodRaySampling sampling) {
  create.features = create.features | postfx::testing::BenchmarkFloor;
  postfx::Context* context = nullptr;
  if (postfx::create(create, context) != postfx::Result::Ok) {
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
  return ok;
}

}  // namespace ocean::validation
