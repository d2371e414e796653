#include "pattern_sweep.h"

#include <epoxy/gl.h>

#include <array>
#include <cstdio>

#include <pass_runner.h>
#include <pattern_comparison.h>

#include "frame_estimate.h"
#include "headless_session.h"
#include "traced_caustics_pass.h"

namespace ocean {
namespace {

double luminance(const float* rgba) {
  return 0.2126 * double(rgba[0]) + 0.7152 * double(rgba[1]) + 0.0722 * double(rgba[2]);
}

// The options of the sweep's frame with `change` applied.
Options frameOptions(const Options& base, const PatternSweep& sweep, void (*change)(Options&)) {
  Options options = base;
  options.preset = sweep.preset;
  options.width = sweep.width;
  options.height = sweep.height;
  if (sweep.frame != nullptr) sweep.frame(options);
  if (change != nullptr) change(options);
  return options;
}

// The sweep's frame with `change` applied to its options, rendered once: the session for
// whatever the caller reads of it.
bool renderFrame(const Options& base, const PatternSweep& sweep, void (*change)(Options&),
                 bool benchmarkFloor, HeadlessSession& session, std::string& error) {
  const Options options = frameOptions(base, sweep, change);
  if (!openHeadlessSession(options, /*debug=*/false, benchmarkFloor, session, error)) return false;
  const FrameInput input{session.preset.camera, session.preset.sun, options.timeSeconds};
  return session.renderer->render(input, error);
}

// Each pixel's added light: luminance of `frame` minus `base`'s.
std::vector<double> addedLight(const std::vector<float>& frame, const std::vector<float>& base) {
  std::vector<double> light(frame.size() / 4);
  for (std::size_t i = 0; i < light.size(); ++i)
    light[i] = luminance(&frame[4 * i]) - luminance(&base[4 * i]);
  return light;
}

}  // namespace

bool measurePatternSweep(const Options& base, const PatternSweep& sweep,
                         std::vector<report::Row>& rows, PatternSweepTrace& traced,
                         std::string& error) {
  // The frame without the light (the base), then the same frame with the light traced: the
  // reference, and which pixels it lights.
  HeadlessSession session;
  if (!renderFrame(base, sweep, sweep.unlit, false, session, error)) return false;
  const std::vector<float> baseFrame = session.renderer->readRadiance();
  reference::FrameTraceDesc trace = frameTraceOptions(base);
  trace.reflected = sweep.reflected;
  const std::string name = sweep.name;
  trace.progress = [name](const reference::FrameTraceProgress& p) {
    std::fprintf(stderr, "report: %s reference, batch %d, noise p99 %.2f %%, %.0f s\n",
                 name.c_str(), p.batch, 100.0 * p.noiseQuantile, p.seconds);
  };
  const FrameInput input{session.preset.camera, session.preset.sun, base.timeSeconds};
  auto pass = TracedCausticsPass::create(*session.plugin, session.scene, input.camera.position,
                                         trace, error);
  if (!pass) return false;
  const PluginPass plugin = session.renderer->pluginPass();
  TracedCausticsPass* tracer = pass.get();
  session.renderer->setPluginPass([plugin, tracer](const HostFrame& frame, std::string& message) {
    return plugin(frame, message) && tracer->run(frame, message);
  });
  if (!session.renderer->render(input, error)) return false;
  const std::vector<double> reference = addedLight(session.renderer->readRadiance(), baseFrame);
  const reference::FrameTraceResult& result = tracer->result();
  const std::vector<std::uint8_t>& lit = sweep.reflected ? result.reflectedLit : result.lit;
  std::vector<std::uint8_t> mask(lit.begin(), lit.end());
  traced = {double(result.photons), result.batches,
            sweep.reflected ? result.reflectedNoiseQuantile : result.noiseQuantile,
            result.converged};

  // The estimates' class (PassRun::estimatedMs): the RTX 3060's at 1920x1080.
  std::vector<cost::GpuClass> gpus;
  if (validation::estimatingRuns() && !cost::selectGpuClasses("rtx3060", gpus, error)) return false;
  const cost::GpuClass gpu = gpus.empty() ? cost::GpuClass{} : gpus[0];

  HeadlessSession flatSession;
  if (!renderFrame(base, sweep, sweep.flat, false, flatSession, error)) return false;
  const std::vector<double> flatLight = addedLight(flatSession.renderer->readRadiance(), baseFrame);

  for (const int value : sweep.values) {
    std::fprintf(stderr, "report: %s, %s %d\n", sweep.name.c_str(), sweep.settingLabel.c_str(),
                 value);
    HeadlessSession measured;
    Options options = base;
    sweep.setting(options, value);
    if (!renderFrame(options, sweep, nullptr, /*benchmarkFloor=*/true, measured, error))
      return false;
    const std::vector<double> method = addedLight(measured.renderer->readRadiance(), baseFrame);
    const reference::PatternComparison c =
        reference::comparePatterns(method, reference, flatLight, mask, sweep.width, sweep.height);
    // The same frame again and again: the pass's median time and the floor's.
    const FrameInput still{measured.preset.camera, measured.preset.sun, base.timeSeconds};
    for (int f = 0; f < sweep.timedFrames + postfx::kTimerRingDepth; ++f)
      if (!measured.renderer->render(still, error)) return false;
    glFinish();
    for (int f = 0; f < postfx::kTimerRingDepth; ++f)
      if (!measured.renderer->render(still, error)) return false;
    const postfx::FrameStats& stats = measured.plugin->stats();
    report::Row row;
    row.pass = postfx::toString(sweep.pass);
    row.method = sweep.method;
    row.setting = sweep.settingLabel + " " + std::to_string(value);
    row.medianMs = stats.pass(sweep.pass).medianMs;
    row.floorMs = stats.pass(postfx::Pass::Floor).medianMs;
    if (validation::estimatingRuns()) {
      std::array<double, postfx::kPassCount> estimated{};
      if (!estimatePasses(measured, frameOptions(options, sweep, nullptr), gpu, 1920.0 * 1080.0,
                          true, estimated, error))
        return false;
      row.estimatedMs = estimated[static_cast<int>(sweep.pass)];
    }
    row.relativeRmse = c.relativeRmse;
    row.correlation = c.correlation;
    row.contrast = c.methodContrast;
    row.referenceContrast = c.referenceContrast;
    row.width = sweep.width;
    row.height = sweep.height;
    row.note = "pattern over " + std::to_string(c.pixels) + " pixels";
    rows.push_back(row);
  }
  return true;
}

}  // namespace ocean
