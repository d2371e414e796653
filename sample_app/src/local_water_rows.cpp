#include "local_water_rows.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <cstdio>

#include <pattern_comparison.h>

#include "headless_session.h"
#include "traced_caustics_pass.h"

namespace ocean {
namespace {

double luminance(const float* rgba) {
  return 0.2126 * double(rgba[0]) + 0.7152 * double(rgba[1]) + 0.0722 * double(rgba[2]);
}

// The pool's frame at the settings' size with `change` applied to its options, rendered once:
// its radiance, and the session for whatever the caller reads of it.
bool renderPool(const Options& base, const LocalWaterReportSettings& settings,
                void (*change)(Options&), bool benchmarkFloor, HeadlessSession& session,
                std::string& error) {
  Options options = base;
  options.preset = "pool";
  // No god rays in any of the frames: flat water's frame (ray deviation at tau 0) would light
  // its shafts otherwise than the others, and they would count as caustic light.
  options.godRays = false;
  options.width = settings.width;
  options.height = settings.height;
  if (change != nullptr) change(options);
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

bool measureLocalWaterRows(const Options& base, const LocalWaterReportSettings& settings,
                           std::vector<report::Row>& rows, std::string& note, std::string& error) {
  // The frame without the plugin's caustics (the base), then the same frame with the pool's
  // light traced through its simulation texture: the reference, and which pixels it lights.
  HeadlessSession traced;
  auto noCaustics = [](Options& o) {
    o.caustics = false;
    o.objectCaustics = false;
  };
  if (!renderPool(base, settings, noCaustics, false, traced, error)) return false;
  const std::vector<float> baseFrame = traced.renderer->readRadiance();
  reference::FrameTraceDesc trace = frameTraceOptions(base);
  trace.progress = [](const reference::FrameTraceProgress& p) {
    std::fprintf(stderr, "report: local water reference, batch %d, noise p99 %.2f %%, %.0f s\n",
                 p.batch, 100.0 * p.noiseQuantile, p.seconds);
  };
  const FrameInput input{traced.preset.camera, traced.preset.sun, base.timeSeconds};
  auto pass =
      TracedCausticsPass::create(*traced.plugin, traced.scene, input.camera.position, trace, error);
  if (!pass) return false;
  const PluginPass plugin = traced.renderer->pluginPass();
  TracedCausticsPass* tracer = pass.get();
  traced.renderer->setPluginPass([plugin, tracer](const HostFrame& frame, std::string& message) {
    return plugin(frame, message) && tracer->run(frame, message);
  });
  if (!traced.renderer->render(input, error)) return false;
  const std::vector<double> reference = addedLight(traced.renderer->readRadiance(), baseFrame);
  const reference::FrameTraceResult& result = tracer->result();
  std::vector<std::uint8_t> mask(result.lit.begin(), result.lit.end());

  // Flat water's frame: the regions flat, the plugin's factor 1 (ray deviation at tau 0).
  HeadlessSession flatSession;
  auto flat = [](Options& o) {
    o.objectCaustics = false;
    o.flatLocalWater = true;
    o.rayDeviationCaustics = true;
    o.tau = 0.0;
  };
  if (!renderPool(base, settings, flat, false, flatSession, error)) return false;
  const std::vector<double> flatLight = addedLight(flatSession.renderer->readRadiance(), baseFrame);

  for (const int grid : settings.grids) {
    std::fprintf(stderr, "report: local water, grid %d\n", grid);
    HeadlessSession session;
    Options options = base;
    options.localWaterGrid = grid;
    options.objectCaustics = false;
    if (!renderPool(options, settings, nullptr, /*benchmarkFloor=*/true, session, error))
      return false;
    const std::vector<double> method = addedLight(session.renderer->readRadiance(), baseFrame);
    const reference::PatternComparison c = reference::comparePatterns(
        method, reference, flatLight, mask, settings.width, settings.height);
    // The same frame again and again: the pass's median time and the floor's.
    const FrameInput still{session.preset.camera, session.preset.sun, base.timeSeconds};
    for (int f = 0; f < settings.timedFrames + postfx::kTimerRingDepth; ++f)
      if (!session.renderer->render(still, error)) return false;
    glFinish();
    for (int f = 0; f < postfx::kTimerRingDepth; ++f)
      if (!session.renderer->render(still, error)) return false;
    const postfx::FrameStats& stats = session.plugin->stats();
    report::Row row;
    row.pass = "local_water";
    row.method = "local water, the pool (Replace)";
    row.setting = "grid " + std::to_string(grid);
    row.medianMs = stats.pass(postfx::Pass::LocalWater).medianMs;
    row.floorMs = stats.pass(postfx::Pass::Floor).medianMs;
    row.relativeRmse = c.relativeRmse;
    row.correlation = c.correlation;
    row.contrast = c.methodContrast;
    row.referenceContrast = c.referenceContrast;
    row.width = settings.width;
    row.height = settings.height;
    row.note = "pattern over " + std::to_string(c.pixels) + " pixels";
    rows.push_back(row);
  }
  char text[512];
  std::snprintf(text, sizeof(text),
                "Local water: the pool preset at %dx%d (its simulation at rest 4 s before t = "
                "%.3g s, then its drops and ball), traced once through the simulation's texture "
                "(%.3g photons in %d batches, lit-pixel noise p99 %.2f %%, %s); each grid's "
                "pattern (added light / flat water's) against it, the pass timed over %d frames "
                "with the floor.",
                settings.width, settings.height, base.timeSeconds, double(result.photons),
                result.batches, 100.0 * result.noiseQuantile,
                result.converged ? "converged" : "NOT converged", settings.timedFrames);
  note = text;
  return true;
}

}  // namespace ocean
