// ocean_sample bench: per-pass GPU time of the plugin on the default scene, and each pass's
// ratio to the floor pass measured in the same run (the only number comparable across
// machines without a GPU). Also the water spectrum update's cost per resolution.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <glcontext/context.h>

#include "camera.h"
#include "commands.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "scene_setup.h"
#include "water_bench.h"

namespace ocean {
namespace {

constexpr int kWarmupFrames = 8;

int fail(const std::string& message) {
  std::fprintf(stderr, "ocean_sample: %s\n", message.c_str());
  return 1;
}

std::string jsonEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    if (static_cast<unsigned char>(c) >= 0x20) out += c;
  }
  return out;
}

}  // namespace

int runBench(const Options& options) {
  std::string error, known;
  Preset preset;
  if (!findPreset(options.preset, preset, known)) {
    return fail("unknown preset '" + options.preset + "' (known: " + known + ")");
  }
  ocean_scene::Model scene;
  if (!buildScene(options.models, scene, error)) return fail(error);
  auto context = glcontext::HeadlessContext::create(/*debug=*/false, error);
  if (!context) return fail(error);
  RenderSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.waterResolution = options.waterResolution;
  auto renderer = Renderer::create(settings, scene, error);
  if (!renderer) return fail(error);
  auto plugin = PluginSetup::create(*renderer, options, /*benchmarkFloor=*/true, error);
  if (!plugin) return fail(error);

  // The camera holds still while time runs, as in a game; each frame is a full render.
  FrameInput input{preset.camera, preset.sun, options.timeSeconds};
  const int total = kWarmupFrames + options.frames;
  for (int frame = 0; frame < total; ++frame) {
    input.timeSeconds = options.timeSeconds + frame / 60.0;
    if (!renderer->render(input, error)) return fail(error);
    if (frame % 10 == 0) std::fprintf(stderr, "\rbench: frame %d/%d", frame + 1, total);
  }
  glFinish();
  // A few more dispatches so the last measured frames' queries resolve (the ring never stalls).
  for (int frame = 0; frame < postfx::kTimerRingDepth; ++frame) {
    if (!renderer->render(input, error)) return fail(error);
  }
  std::fprintf(stderr, "\rbench: %d frames measured        \n", options.frames);

  const postfx::FrameStats& stats = plugin->stats();
  double floorMs = 0.0;
  for (int i = 0; i < stats.passCount; ++i) {
    if (std::string(stats.passes[i].name) == "floor") floorMs = stats.passes[i].medianMs;
  }
  std::ostringstream json;
  json << "{\"device\": \"" << jsonEscape(context->renderer()) << "\", \"width\": " << options.width
       << ", \"height\": " << options.height << ", \"preset\": \"" << options.preset
       << "\", \"frames\": " << options.frames << ", \"passes\": [";
  std::printf("device: %s\n%dx%d, preset %s, %d frames (median after %d warm-up)\n\n",
              context->renderer().c_str(), options.width, options.height, options.preset.c_str(),
              options.frames, kWarmupFrames);
  std::printf("%-16s %12s %12s\n", "pass", "median ms", "floor ratio");
  for (int i = 0; i < stats.passCount; ++i) {
    const postfx::PassStats& pass = stats.passes[i];
    const double ratio = floorMs > 0.0 ? pass.medianMs / floorMs : 0.0;
    std::printf("%-16s %12.3f %12.2f%s\n", pass.name, pass.medianMs, ratio,
                pass.skipped ? "  (skipped)" : "");
    json << (i ? ", " : "") << "{\"name\": \"" << pass.name
         << "\", \"median_ms\": " << pass.medianMs << ", \"floor_ratio\": " << ratio << "}";
  }
  json << "]}\n";

  std::printf("\nwater spectrum update (GPU time per frame, memory held):\n");
  std::ostringstream waterTable;
  if (runWaterBench(waterTable, std::min(options.frames, 30)) != 0) {
    return fail("water benchmark failed");
  }
  std::fputs(waterTable.str().c_str(), stdout);

  if (!options.json.empty()) {
    std::ofstream file(options.json);
    file << json.str();
    if (!file) return fail("cannot write '" + options.json + "'");
  }
  return 0;
}

}  // namespace ocean
