// postfx_bench: the plugin's GPU cost on its own, for machines where only a GPU driver can be
// assumed (no OpenImageIO, no GLFW: the plugin, the water module, EGL). A CPU-made seabed
// G-buffer (seabed_gbuffer.h), the water module's 3-cascade FFT ocean animating every frame, and
// one fresh plugin context per configuration with the benchmark floor beside it: each row is the
// median GPU time of the configuration's passes and its ratio to the floor measured in the same
// run (a full-screen pass reading the same inputs with no math), the number comparable across
// machines. Prints a table; --json FILE writes the rows too. --work also runs each configuration
// once with the work account counted in its shaders and prints, beside the measured time, each
// GPU class's ESTIMATE of it (docs/gpu_cost.md; --gpu names the classes), the shaders'
// arithmetic read from Mesa's dump here (--write-alu FILE keeps it) or from a file written so on
// another machine (--alu FILE): a GPU's driver prints none.
#include <epoxy/gl.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <glcontext/context.h>
#include <postfx/postfx.h>
#include <postfx/testing.h>
#include <postfx/water/ocean.h>
#include <nlohmann/json.hpp>

#include "gpu_cost.h"
#include "seabed_gbuffer.h"
#include "shader_statistics.h"

namespace {

constexpr int kWarmupFrames = 8;

struct Options {
  int width = 1920, height = 1080, frames = postfx::kTimerMedianWindow;
  std::string json;
  std::string only;  // run only the rows whose name starts with this
  bool work = false;
  std::string gpu = "rtx3060";
  std::string alu, writeAlu;  // program statistics: read from, written to
};

struct Config {
  std::string name;
  postfx::Feature features;
  postfx::CausticsSettings caustics;
  postfx::GodRaySettings godRays;
  std::vector<postfx::Pass> passes;      // the passes whose times make the configuration's cost
  std::vector<postfx::Pass> shown = {};  // passes listed beside them, not counted
};

struct Row {
  std::string name;
  double ms = 0.0, floorMs = 0.0;
  std::vector<std::pair<std::string, double>> passes, shown;
  std::vector<std::pair<std::string, double>> estimates;  // per GPU class, the counted passes'
};

bool parse(int argc, char** argv, Options& options, std::string& error) {
  for (int i = 1; i < argc; ++i) {
    const std::string flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      error =
          "usage: postfx_bench [--width W] [--height H] [--frames N] [--json FILE] [--only "
          "PREFIX] [--work [--gpu NAMES] [--alu FILE]] [--write-alu FILE]";
      return false;
    }
    if (flag == "--work") {
      options.work = true;
      continue;
    }
    if (i + 1 >= argc) {
      error = flag + " needs a value (try --help)";
      return false;
    }
    const std::string value = argv[++i];
    char* end = nullptr;
    const long number = std::strtol(value.c_str(), &end, 10);
    const bool integer = end != value.c_str() && *end == '\0';
    if (flag == "--json") {
      options.json = value;
    } else if (flag == "--only") {
      options.only = value;
    } else if (flag == "--gpu") {
      options.gpu = value;
    } else if (flag == "--alu") {
      options.alu = value;
    } else if (flag == "--write-alu") {
      options.writeAlu = value;
    } else if (flag == "--width" && integer && number >= 16 && number <= 8192) {
      options.width = int(number);
    } else if (flag == "--height" && integer && number >= 16 && number <= 8192) {
      options.height = int(number);
    } else if (flag == "--frames" && integer && number >= 1 && number <= 10000) {
      options.frames = int(number);
    } else {
      error = "bad option " + flag + " " + value + " (try --help)";
      return false;
    }
  }
  return true;
}

std::vector<Config> configurations() {
  using postfx::Feature;
  using postfx::Pass;
  std::vector<Config> configs;
  postfx::GodRaySettings noGodRays;
  noGodRays.enabled = false;
  const Feature caustics = Feature::Caustics | Feature::Dispersion;
  // The default model: the tile irradiance, its pre-pass counted.
  configs.push_back({"caustics", caustics, {}, noGodRays, {Pass::TileIrradiance, Pass::Caustics}});
  postfx::CausticsSettings rayDeviation;
  rayDeviation.model = postfx::CausticsModel::RayDeviation;
  configs.push_back(
      {"caustics_ray_deviation", caustics, rayDeviation, noGodRays, {Pass::Caustics}});
  for (auto [resolution, layers] : {std::pair{64, 4}, std::pair{256, 4}, std::pair{128, 8}}) {
    postfx::CausticsSettings tile;
    tile.tileResolution = resolution;
    tile.tileDepthLayers = layers;
    configs.push_back(
        {"caustics_tile_" + std::to_string(resolution) + "_" + std::to_string(layers) + "layers",
         caustics,
         tile,
         noGodRays,
         {Pass::TileIrradiance, Pass::Caustics}});
  }
  for (int grid : {128, 256}) {
    postfx::CausticsSettings physical;
    physical.model = postfx::CausticsModel::WavefrontAreaRatio;
    physical.gridResolution = grid;
    configs.push_back({"wavefront_area_ratio_" + std::to_string(grid),
                       caustics | Feature::WavefrontAreaRatio,
                       physical,
                       noGodRays,
                       // The tile irradiance continues the window: its pre-pass runs too.
                       {Pass::WavefrontAreaRatio, Pass::TileIrradiance, Pass::Caustics}});
  }
  // God rays alone (no seabed caustics): the default model's shafts read the tile irradiance,
  // whose pre-pass then runs for them (shown, not counted: a default frame shares it with the
  // caustics); ray_deviation: the ray-deviation factor from the slopes at every sample.
  postfx::CausticsSettings noCaustics;
  noCaustics.enabled = false;
  postfx::CausticsSettings noCausticsRayDeviation = noCaustics;
  noCausticsRayDeviation.model = postfx::CausticsModel::RayDeviation;
  for (auto [resolution, label] : {std::pair{postfx::GodRayResolution::Full, "full"},
                                   std::pair{postfx::GodRayResolution::Half, "half"},
                                   std::pair{postfx::GodRayResolution::Quarter, "quarter"}}) {
    postfx::GodRaySettings godRays;
    godRays.resolution = resolution;
    configs.push_back({std::string("god_rays_") + label + "_16",
                       Feature::Caustics | Feature::GodRays,
                       noCaustics,
                       godRays,
                       {Pass::GodRays},
                       {Pass::TileIrradiance}});
    configs.push_back({std::string("god_rays_ray_deviation_") + label + "_16",
                       Feature::Caustics | Feature::GodRays,
                       noCausticsRayDeviation,
                       godRays,
                       {Pass::GodRays}});
  }
  configs.push_back({"default_frame",
                     caustics | Feature::GodRays,
                     {},
                     {},
                     {Pass::TileIrradiance, Pass::Caustics, Pass::GodRays}});
  return configs;
}

postfx::FrameDesc describe(const Config& config, const postfx::bench::SeabedGbuffer& gbuffer,
                           const postfx::water::Ocean& ocean) {
  const postfx::bench::SeabedView& view = gbuffer.view();
  postfx::FrameDesc frame;
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), GL_RGBA16F};
  frame.albedo = {gbuffer.albedo(), GL_RGBA8};
  frame.target = {gbuffer.target(), GL_RGBA16F};
  frame.camera.position = view.eye;
  frame.camera.view = glm::mat4(view.view);
  frame.camera.projection = view.projection;
  frame.sun.direction = glm::normalize(glm::dvec3(0.35, 1.0, -0.25));
  frame.water.texture = {ocean.slopeTexture(), GL_RGBA16F};
  frame.water.cascadeCount = ocean.cascadeCount();
  for (int c = 0; c < ocean.cascadeCount(); ++c) {
    frame.water.tileSize[c] = ocean.tileSize(c);
    frame.water.rmsLaplacian[c] = ocean.waveStats(c).rmsLaplacian;
    frame.water.longestWavelength[c] = ocean.waveStats(c).longestWavelength;
  }
  frame.caustics = config.caustics;
  frame.godRays = config.godRays;
  return frame;
}

// A context for `config` (its features and `extra`), `frames` frames dispatched with the ocean
// animating, the GPU drained before the last kTimerRingDepth (whose dispatches read the rest
// back); `done` sees the context before it goes.
bool dispatchFrames(const Config& config, postfx::Feature extra, bool workAccount, int frames,
                    const postfx::bench::SeabedGbuffer& gbuffer, postfx::water::Ocean& ocean,
                    const std::function<void(const postfx::Context&)>& done, std::string& error) {
  postfx::CreateDesc create;
  create.features = config.features | extra;
  create.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  create.normalEncoding = postfx::NormalEncoding::WorldXyz;
  create.maxWaterCascades = ocean.cascadeCount();
  create.workAccount = workAccount;
  postfx::Context* fx = nullptr;
  if (postfx::create(create, fx) != postfx::Result::Ok) {
    error = std::string("postfx: ") + postfx::lastError(nullptr);
    return false;
  }
  const postfx::FrameDesc frame = describe(config, gbuffer, ocean);
  GLuint framebuffer = 0;
  glCreateFramebuffers(1, &framebuffer);
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, gbuffer.target(), 0);
  const int total = frames + postfx::kTimerRingDepth;
  bool ok = true;
  for (int i = 0; i < total && ok; ++i) {
    // The measured frames' queries resolve in the last kTimerRingDepth ones (never stalled).
    if (i == frames) glFinish();
    ok = ocean.update(i / 60.0, error) == postfx::water::Result::Ok;
    // A host's lighting pass fills the target before the plugin adds to it: here a clear through
    // a framebuffer, which also keeps 80 frames of added light from saturating the half floats.
    // (Between the ocean's compute update and the first timed pass it also gives llvmpipe's
    // GL_TIME_ELAPSED a sane start: right after compute work it reports the absolute time.)
    const float black[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glClearNamedFramebufferfv(framebuffer, GL_COLOR, 0, black);
    if (ok && postfx::dispatch(*fx, frame) != postfx::Result::Ok) {
      error = std::string("postfx: ") + postfx::lastError(fx);
      ok = false;
    }
  }
  if (ok) done(*fx);
  postfx::destroy(fx);
  glDeleteFramebuffers(1, &framebuffer);
  return ok;
}

// The configuration's time (its own floor beside it); with `programs`, the driver's dump of the
// programs it builds is read into it (Mesa, after cost::requestMesaShaderDump).
bool run(const Config& config, const Options& options, const postfx::bench::SeabedGbuffer& gbuffer,
         postfx::water::Ocean& ocean, Row& row,
         std::map<std::string, ocean::cost::ProgramStatistics>* programs, std::string& error) {
  std::unique_ptr<ocean::cost::ShaderDumpCapture> capture;
  if (programs != nullptr) capture = std::make_unique<ocean::cost::ShaderDumpCapture>();
  return dispatchFrames(
      config, postfx::testing::BenchmarkFloor, false, kWarmupFrames + options.frames, gbuffer,
      ocean,
      [&](const postfx::Context& fx) {
        const postfx::FrameStats& stats = postfx::stats(fx);
        row.name = config.name;
        row.floorMs = stats.pass(postfx::Pass::Floor).medianMs;
        for (const postfx::Pass pass : config.passes) {
          row.passes.emplace_back(postfx::toString(pass), stats.pass(pass).medianMs);
          row.ms += row.passes.back().second;
        }
        for (const postfx::Pass pass : config.shown)
          row.shown.emplace_back(postfx::toString(pass), stats.pass(pass).medianMs);
        // While the context lives: its programs' labels.
        if (programs != nullptr)
          for (auto& [label, p] : ocean::cost::labelled(ocean::cost::parseNirDump(capture->text())))
            (*programs)[label] = p;
      },
      error);
}

// The configuration's work counted in one frame, estimated on `gpus`: its counted passes' steps.
bool estimate(const Config& config, const postfx::bench::SeabedGbuffer& gbuffer,
              postfx::water::Ocean& ocean, const std::vector<ocean::cost::GpuClass>& gpus,
              const std::map<std::string, ocean::cost::ProgramStatistics>& programs, Row& row,
              std::string& error) {
  return dispatchFrames(
      config, postfx::testing::CountShaderWork, true, 1, gbuffer, ocean,
      [&](const postfx::Context& fx) {
        const postfx::WorkSteps steps = postfx::workSteps(fx);
        for (const ocean::cost::GpuClass& gpu : gpus) {
          double ms = 0.0;
          for (int i = 0; i < steps.count; ++i) {
            const postfx::WorkStep& s = steps.steps[i];
            if (std::find(config.passes.begin(), config.passes.end(), s.pass) ==
                config.passes.end())
              continue;
            const auto p = programs.find(ocean::cost::programLabel(s.program));
            const ocean::cost::StepAlu alu = p == programs.end()
                                                 ? ocean::cost::StepAlu{}
                                                 : ocean::cost::stepAlu(p->second, s.work);
            ms += ocean::cost::estimate(s, alu, gpu).seconds * 1e3;
          }
          row.estimates.emplace_back(gpu.name, ms);
        }
      },
      error);
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  std::string error;
  if (!parse(argc, argv, options, error)) {
    std::fprintf(stderr, "postfx_bench: %s\n", error.c_str());
    return error.rfind("usage:", 0) == 0 ? 0 : 2;
  }
  std::vector<ocean::cost::GpuClass> gpus;
  if (options.work && !ocean::cost::selectGpuClasses(options.gpu, gpus, error)) {
    std::fprintf(stderr, "postfx_bench: %s\n", error.c_str());
    return 2;
  }
  // The shaders' arithmetic: from a file, else (Mesa) from the driver's dump of each program.
  std::map<std::string, ocean::cost::ProgramStatistics> programs;
  if (!options.alu.empty()) {
    std::ifstream in(options.alu);
    std::ostringstream text;
    text << in.rdbuf();
    if (!in || !ocean::cost::readStatistics(text.str(), programs, error)) {
      std::fprintf(stderr, "postfx_bench: --alu %s: %s\n", options.alu.c_str(),
                   in ? error.c_str() : "cannot read it");
      return 2;
    }
  }
  const bool dump = options.alu.empty() && (options.work || !options.writeAlu.empty());
  if (dump) ocean::cost::requestMesaShaderDump();
  auto context = glcontext::HeadlessContext::create(false, error);
  if (!context) {
    std::fprintf(stderr, "postfx_bench: %s\n", error.c_str());
    return 1;
  }
  std::unique_ptr<postfx::water::Ocean> ocean;
  if (postfx::water::Ocean::create(postfx::water::OceanDesc{}, ocean, error) !=
      postfx::water::Result::Ok) {
    std::fprintf(stderr, "postfx_bench: water: %s\n", error.c_str());
    return 1;
  }
  std::fprintf(stderr, "postfx_bench: %s, %d x %d, %d frames per row; building the G-buffer\n",
               context->renderer().c_str(), options.width, options.height, options.frames);
  const postfx::bench::SeabedGbuffer gbuffer(options.width, options.height);

  nlohmann::json json;
  json["renderer"] = context->renderer();
  json["width"] = options.width;
  json["height"] = options.height;
  json["frames"] = options.frames;
  json["seabed_fraction"] = gbuffer.seabedFraction();
  std::printf("%-22s %10s %10s %8s  passes\n", "row", "ms", "floor ms", "ratio");
  const std::vector<Config> configs = configurations();
  for (size_t k = 0; k < configs.size(); ++k) {
    if (configs[k].name.rfind(options.only, 0) != 0) continue;
    std::fprintf(stderr, "postfx_bench: %s (%zu/%zu)\n", configs[k].name.c_str(), k + 1,
                 configs.size());
    Row row;
    if (!run(configs[k], options, gbuffer, *ocean, row, dump ? &programs : nullptr, error) ||
        (options.work && !estimate(configs[k], gbuffer, *ocean, gpus, programs, row, error))) {
      std::fprintf(stderr, "postfx_bench: %s: %s\n", configs[k].name.c_str(), error.c_str());
      return 1;
    }
    const double ratio = row.floorMs > 0.0 ? row.ms / row.floorMs : 0.0;
    std::string passes;
    nlohmann::json entry = {
        {"name", row.name}, {"ms", row.ms}, {"floor_ms", row.floorMs}, {"floor_ratio", ratio}};
    for (const auto& [name, ms] : row.passes) {
      char text[64];
      std::snprintf(text, sizeof(text), " %s %.3f", name.c_str(), ms);
      passes += text;
      entry["passes"][name] = ms;
    }
    for (const auto& [name, ms] : row.shown) {
      char text[64];
      std::snprintf(text, sizeof(text), " (%s %.3f)", name.c_str(), ms);
      passes += text;
      entry["shown"][name] = ms;
    }
    for (const auto& [gpu, ms] : row.estimates) {
      char text[96];
      std::snprintf(text, sizeof(text), "  ESTIMATE %s %.3f ms", gpu.c_str(), ms);
      passes += text;
      entry["estimate_ms"][gpu] = ms;
    }
    std::printf("%-22s %10.3f %10.3f %8.2f %s\n", row.name.c_str(), row.ms, row.floorMs, ratio,
                passes.c_str());
    std::fflush(stdout);
    json["rows"].push_back(entry);
  }
  if (options.work)
    json["estimate"] = "roofline model, docs/gpu_cost.md: an estimate, not a measurement";
  if (!options.writeAlu.empty()) {
    std::ofstream file(options.writeAlu);
    file << ocean::cost::writeStatistics(programs) << "\n";
    if (!file || programs.empty()) {
      std::fprintf(stderr, "postfx_bench: no program statistics for %s (Mesa's dump needed)\n",
                   options.writeAlu.c_str());
      return 1;
    }
  }
  if (!options.json.empty()) {
    std::ofstream file(options.json);
    file << json.dump(2) << "\n";
    if (!file) {
      std::fprintf(stderr, "postfx_bench: could not write %s\n", options.json.c_str());
      return 1;
    }
  }
  return 0;
}
