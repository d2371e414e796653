// ocean_sample bench: per-pass GPU time of the plugin on the default scene, and each pass's
// ratio to the floor pass measured in the same run (the only number comparable across
// machines without a GPU). Also the water spectrum update's cost per resolution.
// God rays: after the default run, one short run per sample count (4..64) at full, half and
// quarter resolution, each with a fresh plugin context (fresh timers) and its own floor measured
// in the same run, reported as rows god_rays_<n>, god_rays_half_<n> and god_rays_quarter_<n>.
// The wavefront area ratio: one short run per grid resolution (64..1024), rows
// wavefront_area_ratio_<n> (its own pass), wavefront_area_ratio_<n>_tile_irradiance (the tile
// pre-pass that continues the window) and wavefront_area_ratio_<n>_caustics (the full-screen
// caustics pass sampling both), with the clamp's bias on stderr.
// Object caustics: likewise one short run per caustic-map size, ray-grid size and hit-iteration
// count, reported as rows object_caustics_<map>_<grid>_<iterations>.
// Several views: the plugin's whole time per frame (every pass but the floor) for 1, 2 and 6
// views of the scene (cameras turned 60 degrees apart) drawn by one context in one dispatch,
// rows views_<n>, against the same views drawn by one context each, rows contexts_<n>.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include <glcontext/context.h>
#include <nlohmann/json.hpp>

#include "camera.h"
#include "commands.h"
#include "headless_session.h"
#include "multi_view.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "shader_statistics.h"
#include "view_flags.h"
#include "water_bench.h"
#include "work_bench.h"

namespace ocean {
namespace {

constexpr int kWarmupFrames = 8;

// Renders warm-up + `frames` frames with time running, then a few more so that the measured
// frames' queries resolve (the plugin's ring never stalls).
bool renderFrames(Renderer& renderer, FrameInput input, double startSeconds, int frames,
                  std::string& error) {
  const int total = kWarmupFrames + frames;
  for (int frame = 0; frame < total; ++frame) {
    input.timeSeconds = startSeconds + frame / 60.0;
    if (!renderer.render(input, error)) return false;
  }
  glFinish();
  for (int frame = 0; frame < postfx::kTimerRingDepth; ++frame) {
    if (!renderer.render(input, error)) return false;
  }
  return true;
}

struct Row {
  std::string name;
  double medianMs, floorMs;
  bool skipped;
};

}  // namespace

int runBench(const Options& commandOptions) {
  std::string error;
  // The work account's arithmetic comes from Mesa's dump of each program it links.
  if (commandOptions.work) cost::requestMesaShaderDump();
  HeadlessSession session;
  if (!openHeadlessSession(commandOptions, /*debug=*/false, /*benchmarkFloor=*/true, session,
                           error)) {
    return commandFailed(error);
  }
  if (commandOptions.work) return runWorkBench(session, commandOptions);
  // The variants start from the settings the preset is shown with.
  const Options options = withPresetCaustics(commandOptions, session.preset);
  Renderer& renderer = *session.renderer;
  const Preset& preset = session.preset;
  const glcontext::HeadlessContext* context = session.context.get();

  // The camera holds still while time runs, as in a game; each frame is a full render.
  FrameInput input{preset.camera, preset.sun, options.timeSeconds};
  std::fprintf(stderr, "bench: default settings, %d frames\n", options.frames);
  if (!renderFrames(renderer, input, options.timeSeconds, options.frames, error)) {
    return commandFailed(error);
  }
  std::vector<Row> rows;
  {
    const postfx::FrameStats& stats = session.plugin->stats();
    const double floorMs = stats.pass(postfx::Pass::Floor).medianMs;
    for (int i = 0; i < postfx::kPassCount; ++i) {
      const postfx::PassStats& pass = stats.passes[i];
      if (pass.present)
        rows.push_back({postfx::toString(postfx::Pass(i)), pass.medianMs, floorMs, pass.skipped});
    }
  }
  // Variants: same scene and frames, one fresh context each (a context's timers keep a median
  // window, so reusing one would mix settings); the newest becomes the renderer's pass.
  const int variantFrames = std::max(1, std::min(options.frames, 20));
  auto wanted = [&](const std::string& name) { return name.starts_with(options.only); };
  auto runVariant =
      [&](const std::string& label, const Options& variantOptions,
          const std::function<void(PluginSetup&)>& configure) -> const postfx::FrameStats* {
    std::fprintf(stderr, "bench: %s, %d frames\n", label.c_str(), variantFrames);
    auto variant = PluginSetup::create(renderer, variantOptions, /*benchmarkFloor=*/true, error);
    if (!variant) return nullptr;
    configure(*variant);
    session.plugin = std::move(variant);
    if (!renderFrames(renderer, input, options.timeSeconds, variantFrames, error)) return nullptr;
    return &session.plugin->stats();
  };
  auto addRow = [&](const std::string& name, const postfx::FrameStats& stats, postfx::Pass pass) {
    const double ms = stats.pass(pass).medianMs;
    rows.push_back({name, ms, stats.pass(postfx::Pass::Floor).medianMs, ms == 0.0});
  };

  // Caustics sampling every cascade everywhere (no skipping): what the skipping saves.
  if (options.caustics && wanted("caustics_all_cascades")) {
    const postfx::FrameStats* stats =
        runVariant("caustics_all_cascades", options, [](PluginSetup& variant) {
          variant.caustics().minCascadeContrast = 0.0f;
          variant.godRays().enabled = false;
        });
    if (!stats) return commandFailed(error);
    addRow("caustics_all_cascades", *stats, postfx::Pass::Caustics);
  }
  // Seed 002's world-axis projections on steep surfaces: what leaving them out saves.
  if (options.caustics && wanted("caustics_triplanar_walls")) {
    Options triplanar = options;
    triplanar.triplanarWalls = true;
    const postfx::FrameStats* stats =
        runVariant("caustics_triplanar_walls", triplanar,
                   [](PluginSetup& variant) { variant.godRays().enabled = false; });
    if (!stats) return commandFailed(error);
    addRow("caustics_triplanar_walls", *stats, postfx::Pass::Caustics);
  }
  if (options.godRays) {
    const struct {
      const char* prefix;
      postfx::GodRayResolution resolution;
    } resolutions[] = {{"god_rays_", postfx::GodRayResolution::Full},
                       {"god_rays_half_", postfx::GodRayResolution::Half},
                       {"god_rays_quarter_", postfx::GodRayResolution::Quarter}};
    for (const auto& resolution : resolutions) {
      for (int samples : {4, 8, 16, 32, 64}) {
        const std::string name = resolution.prefix + std::to_string(samples);
        if (!wanted(name)) continue;
        const postfx::FrameStats* stats = runVariant(name, options, [&](PluginSetup& variant) {
          variant.godRays().sampleCount = samples;
          variant.godRays().resolution = resolution.resolution;
        });
        if (!stats) return commandFailed(error);
        addRow(name, *stats, postfx::Pass::GodRays);
      }
    }
  }
  if (options.caustics) {
    for (int grid : {64, 128, 256, 512, 1024}) {
      const std::string n = std::to_string(grid);
      const std::string row = "wavefront_area_ratio_" + n;
      if (!wanted(row) && !wanted(row + "_tile_irradiance") && !wanted(row + "_caustics")) continue;
      Options physical = options;
      physical.physicalCaustics = true;
      physical.causticsGrid = grid;
      const postfx::FrameStats* stats = runVariant(row, physical, [](PluginSetup&) {});
      if (!stats) return commandFailed(error);
      addRow(row, *stats, postfx::Pass::WavefrontAreaRatio);
      addRow(row + "_tile_irradiance", *stats, postfx::Pass::TileIrradiance);
      addRow(row + "_caustics", *stats, postfx::Pass::Caustics);
      std::fprintf(stderr, "bench: grid %d: clamp removed %.4f %% of the window's flux\n", grid,
                   100.0 * stats->clampedFluxFraction);
    }
  }
  if (options.objectCaustics) {
    struct Variant {
      int map, grid, iterations;
    };
    for (const Variant& v : {Variant{256, 128, 1}, Variant{512, 256, 1}, Variant{512, 256, 3},
                             Variant{1024, 512, 3}}) {
      const std::string name = "object_caustics_" + std::to_string(v.map) + "_" +
                               std::to_string(v.grid) + "_" + std::to_string(v.iterations);
      if (!wanted(name)) continue;
      const postfx::FrameStats* stats = runVariant(name, options, [&](PluginSetup& variant) {
        variant.objectCaustics().mapSize = v.map;
        variant.objectCaustics().gridSize = v.grid;
        variant.objectCaustics().iterations = v.iterations;
      });
      if (!stats) return commandFailed(error);
      addRow(name, *stats, postfx::Pass::ObjectCaustics);
    }
  }

  bool viewRows = false;
  for (const char* row :
       {"views_1", "views_2", "views_6", "contexts_1", "contexts_2", "contexts_6"})
    viewRows = viewRows || wanted(row);
  if (viewRows) {
    auto views = MultiView::create(renderer, session.scene, 6, error);
    if (!views) return commandFailed(error);
    const int total = kWarmupFrames + variantFrames + postfx::kTimerRingDepth;
    auto inputsFor = [&](int count, double seconds) {
      std::vector<FrameInput> inputs;
      for (int i = 0; i < count; ++i) {
        FrameInput view = input;
        view.camera.yaw += glm::radians(60.0) * i;
        view.timeSeconds = seconds;
        inputs.push_back(view);
      }
      return inputs;
    };
    // The plugin's time in a frame: every pass but the floor, and the local lights.
    auto planTotal = [](const postfx::FrameStats& s) {
      double ms = 0.0;
      for (int p = 0; p < postfx::kPassCount; ++p)
        if (postfx::Pass(p) != postfx::Pass::Floor && s.passes[p].present)
          ms += s.passes[p].medianMs;
      for (const postfx::PassStats& light : s.lights)
        if (light.present) ms += light.medianMs;
      return ms;
    };
    // Where the time goes: each pass's median, for the notes (stderr).
    auto breakdown = [](const char* who, const postfx::FrameStats& s) {
      std::string line;
      for (int p = 0; p < postfx::kPassCount; ++p)
        if (s.passes[p].present)
          line += std::string(" ") + postfx::toString(postfx::Pass(p)) + " " +
                  std::to_string(s.passes[p].medianMs);
      std::fprintf(stderr, "bench:   %s:%s\n", who, line.c_str());
    };
    for (int count : {1, 2, 6}) {
      const std::string n = std::to_string(count);
      if (!wanted("views_" + n) && !wanted("contexts_" + n)) continue;
      std::fprintf(stderr, "bench: %d views in one dispatch, then %d contexts, %d frames\n", count,
                   count, variantFrames);
      auto shared = PluginSetup::create(renderer, options, /*benchmarkFloor=*/true, error);
      if (!shared) return commandFailed(error);
      for (int frame = 0; frame < total; ++frame)
        if (!views->render(inputsFor(count, options.timeSeconds + frame / 60.0), *shared, nullptr,
                           error))
          return commandFailed(error);
      double multi = planTotal(shared->stats());
      breakdown("shared", shared->stats());
      for (int i = 0; i < count; ++i) {
        multi += planTotal(shared->viewStats(i));
        breakdown(("view " + std::to_string(i)).c_str(), shared->viewStats(i));
      }
      const double floorMs = shared->viewStats(0).pass(postfx::Pass::Floor).medianMs;
      rows.push_back({"views_" + n, multi, floorMs, false});
      shared.reset();
      // One context per view: each renderer's own plugin pass (the primary's first: it updates
      // the ocean the others read).
      std::vector<std::unique_ptr<PluginSetup>> own;
      for (int i = 0; i < count; ++i) {
        own.push_back(PluginSetup::create(views->view(i), options, true, error));
        if (!own.back()) return commandFailed(error);
      }
      for (int frame = 0; frame < total; ++frame) {
        const auto inputs = inputsFor(count, options.timeSeconds + frame / 60.0);
        for (int i = 0; i < count; ++i)
          if (!views->view(i).render(inputs[size_t(i)], error)) return commandFailed(error);
      }
      double separate = 0.0;
      for (size_t i = 0; i < own.size(); ++i) {
        separate += planTotal(own[i]->stats());
        breakdown(("context " + std::to_string(i)).c_str(), own[i]->stats());
      }
      rows.push_back({"contexts_" + n, separate, floorMs, false});
      std::fprintf(stderr, "bench: %d views: %.3f ms in one dispatch, %.3f ms in %d contexts\n",
                   count, multi, separate, count);
      for (int i = 0; i < count; ++i) views->view(i).setPluginPass({});
    }
    // The renderer's plugin pass was the last variant's: give it back its own.
    session.plugin = PluginSetup::create(renderer, options, true, error);
    if (!session.plugin) return commandFailed(error);
  }

  // nlohmann escapes the strings (a driver's renderer name may hold quotes or control bytes).
  nlohmann::json json = {{"device", context->renderer()}, {"width", options.width},
                         {"height", options.height},      {"preset", options.preset},
                         {"frames", options.frames},      {"passes", nlohmann::json::array()}};
  std::printf("device: %s\n%dx%d, preset %s, %d frames (median after %d warm-up)\n\n",
              context->renderer().c_str(), options.width, options.height, options.preset.c_str(),
              options.frames, kWarmupFrames);
  std::printf("%-28s %12s %12s\n", "pass", "median ms", "floor ratio");
  for (size_t i = 0; i < rows.size(); ++i) {
    const Row& row = rows[i];
    const double ratio = row.floorMs > 0.0 ? row.medianMs / row.floorMs : 0.0;
    std::printf("%-28s %12.3f %12.2f%s\n", row.name.c_str(), row.medianMs, ratio,
                row.skipped ? "  (skipped)" : "");
    json["passes"].push_back(
        {{"name", row.name}, {"median_ms", row.medianMs}, {"floor_ratio", ratio}});
  }

  std::printf("\nwater spectrum update (GPU time per frame, memory held):\n");
  std::ostringstream waterTable;
  if (runWaterBench(waterTable, std::min(options.frames, 30)) != 0) {
    return commandFailed("water benchmark failed");
  }
  std::fputs(waterTable.str().c_str(), stdout);

  return options.json.empty() ? 0 : writeResultFile(options.json, json.dump(2));
}

}  // namespace ocean
