#pragma once
// Runs one plugin configuration on a host frame the way the report needs it: a fresh context
// (fresh timers), the frame dispatched repeatedly into a report-owned target for the median GPU
// time of the pass and of the floor measured beside it, then once more into a cleared target
// for the image the error is computed from.
#include <epoxy/gl.h>

#include <glkit/handle.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

#include <postfx/postfx.h>
#include <postfx/testing.h>
#include <glm/glm.hpp>

namespace ocean::validation {

struct PassRun {
  double medianMs = 0.0, floorMs = 0.0;  // of the pass asked for and of the floor
  // Every pass the run timed (e.g. WavefrontAreaRatio beside Caustics): one run prices a method
  // made of several passes.
  postfx::FrameStats stats;
  std::vector<glm::vec4> image;  // light the pass added, RGBA32F, GL order
  std::vector<float> raw;        // raw caustic factor (with postfx::testing::RawCausticOutput)
  // The object caustic map of the last frame (rgb, row v = 0 first) and where it lies; empty
  // and texture 0 when the object caustics did not run.
  std::vector<glm::dvec3> objectMap;
  postfx::ObjectCausticMap objectMapPlacement;
  // The cost model's ESTIMATE of each pass of the run (docs/gpu_cost.md), ms, on the RTX 3060
  // class with its per-pixel steps at 1920x1080 (cost::atViewSize): the frame once more with
  // the work counted in the shaders, their arithmetic from Mesa's dump of the timed context's
  // programs (cost::requestMesaShaderDump before the GL context; without it, the invocations'
  // overhead alone). A local light's work counts in Pass::ObjectCaustics.
  // NaN where the run was not estimated (estimateRuns off, or the counted frame failed).
  std::array<double, postfx::kPassCount> estimatedMs{};
  bool hasEstimate = false;
  double estimated(postfx::Pass pass) const {
    return hasEstimate ? estimatedMs[static_cast<int>(pass)]
                       : std::numeric_limits<double>::quiet_NaN();
  }
};

// A GL_RGBA32F target of the frame's size, owned by the report.
class ReportTarget {
 public:
  ReportTarget(int width, int height);
  GLuint texture() const { return texture_.id(); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  glkit::Texture texture_;
  int width_, height_;
};

// Whether every later runPass also estimates its work (PassRun::estimatedMs; a second context
// and frame each): the report turns it on, the tests leave it off.
void estimateRuns(bool on);
bool estimatingRuns();

// `frame`'s target is replaced by `target`; BenchmarkFloor is added to `create.features`.
// `sampling`: the god-ray test hook (postfx/testing.h) for the context.
bool runPass(postfx::CreateDesc create, postfx::FrameDesc frame, postfx::Pass pass,
             const ReportTarget& target, int timedFrames, PassRun& out, std::string& error,
             postfx::testing::GodRaySampling sampling = postfx::testing::GodRaySampling::WorldGrid);

}  // namespace ocean::validation
