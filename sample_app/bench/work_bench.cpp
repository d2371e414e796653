#include "work_bench.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "cpu_calibration.h"
#include "cpu_cost.h"
#include "frame_estimate.h"
#include "gpu_cost.h"
#include "shader_statistics.h"
#include "view_flags.h"

namespace ocean {
namespace {

constexpr int kWarmupFrames = 4;

// A frame's steps summed by name (a pass's per-cascade dispatches, a grid's layers).
struct StepRow {
  std::string name;     // "<pass>.<step>", with " [light i]" for a local light's
  std::string group;    // the name's "<pass>" part: a feature's row
  std::string program;  // its program's debug label
  postfx::WorkStep step;
};

std::vector<StepRow> collect(const postfx::WorkSteps& steps) {
  std::vector<StepRow> rows;
  for (int i = 0; i < steps.count; ++i) {
    const postfx::WorkStep& s = steps.steps[i];
    std::string name = s.name;
    if (s.light >= 0) name += " [light " + std::to_string(s.light) + "]";
    auto it =
        std::find_if(rows.begin(), rows.end(), [&](const StepRow& r) { return r.name == name; });
    if (it == rows.end()) {
      const std::string full = s.name;
      rows.push_back({name, full.substr(0, full.find('.')), cost::programLabel(s.program), s});
      continue;
    }
    it->step.work += s.work;
    it->step.statedFetches += s.statedFetches;
    it->step.statedAtomics += s.statedAtomics;
    it->step.statedBound = it->step.statedBound || s.statedBound;
    it->step.targetBytes = std::max(it->step.targetBytes, s.targetBytes);
    it->step.drainedMs += s.drainedMs;
  }
  return rows;
}

// Everything the tables are made of, measured in four runs of the preset's frame.
struct Measurement {
  std::map<std::string, cost::ProgramStatistics> programs;  // by label: the arithmetic
  std::vector<StepRow> counted;                             // the account counted in the shaders
  // The same with the driver's counts (llvmpipe's lanes), and each step's time alone (a run of
  // its own, without queries).
  std::vector<StepRow> driver;
  postfx::FrameStats timing;   // per pass, without the account, each drained (the floor's)
  std::vector<double> wallMs;  // the same run's dispatches by the CPU's clock
  bool calibrated = false;
  cost::CpuClass cpu;
};

bool measure(HeadlessSession& session, const Options& options, Measurement& m, std::string& error) {
  const int frames = std::max(1, std::min(options.frames, 8));
  const int warmup = options.frames <= 2 ? 1 : kWarmupFrames;  // a smoke run warms up once
  // Only the plain context's first frames' programs are read (they build every variant it
  // uses); the driver's dump of the rest is dropped (cost::ShaderDumpCapture).
  std::fprintf(stderr, "bench --work: the programs' arithmetic (Mesa's NIR)\n");
  {
    cost::ShaderDumpCapture capture;
    if (!usePlugin(session, options, Options::WorkAccount::Off, false, error) ||
        !renderFrames(session, options, 1, error))
      return false;
    m.programs = cost::labelled(cost::parseNirDump(capture.text()));
  }
  std::fprintf(stderr, "bench --work: the account, counted in the shaders, then the driver's\n");
  if (!usePlugin(session, options, Options::WorkAccount::Counted, false, error) ||
      !renderFrames(session, options, warmup + frames, error))
    return false;
  m.counted = collect(session.plugin->workSteps());
  if (!usePlugin(session, options, Options::WorkAccount::Queries, false, error) ||
      !renderFrames(session, options, warmup + frames, error))
    return false;
  m.driver = collect(session.plugin->workSteps());
  // Each step alone by the CPU's clock (testing::TimeEachStep): what the CPU model predicts.
  if (!usePlugin(session, options, Options::WorkAccount::Timed, false, error) ||
      !renderFrames(session, options, warmup + frames, error))
    return false;
  for (const StepRow& timed : collect(session.plugin->workSteps())) {
    for (StepRow& d : m.driver)
      if (d.name == timed.name) d.step.drainedMs = timed.step.drainedMs;
  }
  std::fprintf(stderr, "bench --work: llvmpipe's time per pass, without the account\n");
  if (!usePlugin(session, options, Options::WorkAccount::Off, true, error)) return false;
  session.plugin->measureWallTime(&m.wallMs);
  if (!renderFrames(session, options, warmup + options.frames, error)) return false;
  m.timing = session.plugin->stats();
  // The renderer keeps its ordinary plugin pass.
  if (!usePlugin(session, options, Options::WorkAccount::Off, false, error)) return false;
  if (!m.programs.empty()) {
    std::fprintf(stderr, "bench --work: this machine's costs, one kind of work at a time\n");
    std::string calibrationError;
    m.calibrated = calibrateCpu(m.cpu, calibrationError);
    if (!m.calibrated) std::fprintf(stderr, "bench --work: %s\n", calibrationError.c_str());
  } else {
    std::fprintf(stderr,
                 "bench --work: no NIR from the driver (not Mesa?): the shading term counts "
                 "invocations only, and llvmpipe's model is not checked\n");
  }
  return true;
}

// The budgets the defaults answer to (docs/gpu_cost.md): each feature's steps (by their names'
// first part), estimated on the RTX 3060 class at 1920x1080: 0.5 ms at its defaults, 2 ms at its
// highest setting; on llvmpipe a setting of each within 2x (the frame's) or 10x (the optional
// ones) of the floor.
struct Budget {
  const char* feature;
  std::vector<std::string> groups;
  bool gpu;              // the GPU budgets apply
  double llvmpipeRatio;  // 0: none
};
const Budget kBudgets[] = {
    {"frame: seabed caustics, pre-passes, god rays",
     {"tile_irradiance", "wavefront_area_ratio", "caustics", "god_rays"},
     true,
     0.0},
    {"  seabed caustics and pre-passes",
     {"tile_irradiance", "wavefront_area_ratio", "caustics"},
     false,
     2.0},
    {"  god rays", {"god_rays"}, false, 2.0},
    {"object caustics (with volume caustics when on)",
     {"object_caustics", "volume_caustics"},
     true,
     10.0},
    {"reflected caustics", {"reflected_caustics"}, true, 10.0},
    {"local water", {"local_water"}, true, 10.0},
};
constexpr double kDefaultBudgetMs = 0.5, kHighestBudgetMs = 2.0;

std::string millions(std::uint64_t n) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.2f", double(n) * 1e-6);
  return text;
}

nlohmann::json estimateJson(const cost::StepEstimate& e) {
  return {{"ms", e.seconds * 1e3},          {"bound", e.bound},
          {"shading_ms", e.shading * 1e3},  {"texture_ms", e.texture * 1e3},
          {"memory_ms", e.memory * 1e3},    {"raster_ms", e.raster * 1e3},
          {"rop_ms", e.rop * 1e3},          {"atomics_ms", e.atomics * 1e3},
          {"overhead_ms", e.overhead * 1e3}};
}

// The llvmpipe time a step's pass is timed in: the pass, or the local light's slot.
std::string timedName(const postfx::WorkStep& s) {
  return s.light >= 0 ? std::string("object_caustics [light ") + std::to_string(s.light) + "]"
                      : postfx::toString(s.pass);
}
double timedMs(const postfx::FrameStats& timing, const postfx::WorkStep& s) {
  return s.light >= 0 ? timing.objectLight(s.light).medianMs : timing.pass(s.pass).medianMs;
}

}  // namespace

int runWorkBench(HeadlessSession& session, const Options& commandOptions) {
  std::string error;
  std::vector<cost::GpuClass> gpus;
  if (!cost::selectGpuClasses(commandOptions.gpu, gpus, error)) return commandFailed(error);
  const Options options = withPresetCaustics(commandOptions, session.preset);
  Measurement m;
  if (!measure(session, options, m, error)) return commandFailed(error);

  nlohmann::json json = {
      {"device", session.context->renderer()},
      {"width", options.width},
      {"height", options.height},
      {"preset", options.preset},
      {"estimate", "roofline model, docs/gpu_cost.md: an estimate, not a measurement"},
      {"steps", nlohmann::json::array()},
      {"passes", nlohmann::json::array()}};
  std::printf("work account at %dx%d, preset %s (counted in the shaders); CPU: %s\n", options.width,
              options.height, options.preset.c_str(), session.context->renderer().c_str());
  std::printf(
      "GPU time is an ESTIMATE from the account (docs/gpu_cost.md), not a measurement.\n\n");
  std::printf("%-44s %8s %8s %8s %8s %8s %8s", "step", "invoc M", "prims M", "fetch M", "atomic M",
              "MB", "blend M");
  for (const cost::GpuClass& g : gpus) std::printf(" %11s", (g.name + " ms").c_str());
  std::printf("  bound    %11s %11s\n", "CPU model", "llvmpipe ms");

  // Per feature (the step names' first part) and per timed pass.
  std::map<std::string, std::vector<double>> featureMs;
  std::vector<std::string> features;
  struct PassRow {
    double measured = 0.0, predicted = 0.0;
    std::vector<double> estimate;
  };
  std::map<std::string, PassRow> passes;
  std::vector<std::string> passOrder;
  for (const StepRow& row : m.counted) {
    const postfx::WorkCounts& w = row.step.work;
    std::printf("%-44s %8s %8s %8s %8s %8.2f %8s", row.name.c_str(),
                millions(w.vertices + w.fragments + w.computeInvocations).c_str(),
                millions(w.primitives).c_str(), millions(w.fetches).c_str(),
                millions(w.atomics).c_str(), double(w.bytesRead + w.bytesWritten) / 1e6,
                millions(w.blendedSamples).c_str());
    const auto program = m.programs.find(row.program);
    const cost::StepAlu alu =
        program == m.programs.end() ? cost::StepAlu{} : cost::stepAlu(program->second, w);
    std::vector<double>& featureSums = featureMs[row.group];
    if (featureSums.empty()) {
      featureSums.assign(gpus.size(), 0.0);
      features.push_back(row.group);
    }
    const std::string passName = timedName(row.step);
    PassRow& pass = passes[passName];
    if (pass.estimate.empty()) {
      pass.estimate.assign(gpus.size(), 0.0);
      pass.measured = timedMs(m.timing, row.step);
      passOrder.push_back(passName);
    }
    nlohmann::json estimates = nlohmann::json::object();
    const char* bound = "";
    for (std::size_t g = 0; g < gpus.size(); ++g) {
      const cost::StepEstimate e = cost::estimate(row.step, alu, gpus[g]);
      std::printf(" %11.4f", e.seconds * 1e3);
      featureSums[g] += e.seconds * 1e3;
      pass.estimate[g] += e.seconds * 1e3;
      if (g == 0) bound = e.bound;
      estimates[gpus[g].name] = estimateJson(e);
    }
    std::printf("  %-8s", bound);
    nlohmann::json cpuJson = nullptr;
    const auto driver = std::find_if(m.driver.begin(), m.driver.end(),
                                     [&](const StepRow& d) { return d.name == row.name; });
    if (m.calibrated && driver != m.driver.end()) {
      const cost::StepEstimate e = cost::predictCpu(row.step, driver->step, alu, m.cpu);
      pass.predicted += e.seconds * 1e3;
      std::printf(" %11.3f", e.seconds * 1e3);
      cpuJson = estimateJson(e);
    }
    if (driver != m.driver.end()) std::printf(" %11.3f", driver->step.drainedMs);
    std::printf("\n");
    json["steps"].push_back(
        {{"name", row.name},
         {"pass", passName},
         {"feature", row.group},
         {"program", row.program},
         {"draws", w.draws},
         {"dispatches", w.dispatches},
         {"clears", w.clears},
         {"vertices", w.vertices},
         {"primitives_submitted", w.primitivesSubmitted},
         {"primitives", w.primitives},
         {"fragments", w.fragments},
         {"driver_fragments",
          driver != m.driver.end() ? driver->step.work.fragments : std::uint64_t(0)},
         {"compute_invocations", w.computeInvocations},
         {"samples_passed", w.samplesPassed},
         {"blended_samples", w.blendedSamples},
         {"fetches", w.fetches},
         {"fragment_fetches", w.fragmentFetches},
         {"atomics", w.atomics},
         {"stated_fetches", row.step.statedFetches},
         {"stated_atomics", row.step.statedAtomics},
         {"stated_bound", row.step.statedBound},
         {"bytes_read", w.bytesRead},
         {"bytes_written", w.bytesWritten},
         {"target_bytes", row.step.targetBytes},
         {"alu_per_invocation",
          {{"vertex", alu.vertex.ops},
           {"fragment", alu.fragment.ops},
           {"compute", alu.compute.ops},
           {"vertex_special", alu.vertex.special()},
           {"fragment_special", alu.fragment.special()},
           {"compute_special", alu.compute.special()}}},
         {"estimate", estimates},
         {"llvmpipe_model", cpuJson},
         {"llvmpipe_step_ms", driver != m.driver.end() ? driver->step.drainedMs : 0.0}});
  }

  std::printf("\n%-32s", "feature (GPU estimate)");
  for (const cost::GpuClass& g : gpus) std::printf(" %11s", (g.name + " ms").c_str());
  std::printf("\n");
  for (const std::string& feature : features) {
    std::printf("%-32s", feature.c_str());
    for (double ms : featureMs[feature]) std::printf(" %11.4f", ms);
    std::printf("\n");
  }

  const double floorMs = m.timing.pass(postfx::Pass::Floor).medianMs;
  std::printf("\n%-32s", "pass");
  for (const cost::GpuClass& g : gpus) std::printf(" %11s", (g.name + " ms").c_str());
  std::printf(" %12s %12s %13s %11s\n", "llvmpipe ms", "floor ratio", "CPU model ms",
              "model/meas.");
  for (const std::string& name : passOrder) {
    const PassRow& p = passes[name];
    std::printf("%-32s", name.c_str());
    nlohmann::json estimates = nlohmann::json::object();
    for (std::size_t g = 0; g < gpus.size(); ++g) {
      std::printf(" %11.4f", p.estimate[g]);
      estimates[gpus[g].name] = p.estimate[g];
    }
    const double ratio = p.measured > 0.0 ? p.predicted / p.measured : 0.0;
    std::printf(" %12.3f %12.2f %13.3f %11.2f\n", p.measured,
                floorMs > 0.0 ? p.measured / floorMs : 0.0, p.predicted, ratio);
    json["passes"].push_back({{"name", name},
                              {"estimate_ms", estimates},
                              {"llvmpipe_ms", p.measured},
                              {"llvmpipe_floor_ratio", floorMs > 0.0 ? p.measured / floorMs : 0.0},
                              {"llvmpipe_model_ms", p.predicted},
                              {"llvmpipe_model_over_measured", ratio}});
  }
  std::printf("%-32s", "floor (llvmpipe)");
  for (std::size_t g = 0; g < gpus.size(); ++g) std::printf(" %11s", "");
  std::printf(" %12.3f\n", floorMs);
  json["llvmpipe_floor_ms"] = floorMs;

  // The budgets: each feature present, its estimate on the reference class if it was asked for.
  const auto reference = std::find_if(gpus.begin(), gpus.end(),
                                      [](const cost::GpuClass& g) { return g.name == "rtx3060"; });
  std::printf(
      "\nbudgets (docs/gpu_cost.md): estimated on rtx3060 at 1920x1080, %.1f ms at a "
      "feature's defaults, %.1f at its highest setting%s\n",
      kDefaultBudgetMs, kHighestBudgetMs,
      options.width == 1920 && options.height == 1080 ? "" : " (this run is not at 1920x1080)");
  // Which of the two GPU budgets applies is the run's: its defaults, or a feature's highest.
  std::printf("%-48s %12s %9s %9s %14s %9s\n", "feature", "rtx3060 ms", "<= 0.5", "<= 2",
              "llvmpipe/floor", "2 / 10");
  std::printf("%-48s %12s %9s %9s %14s %9s\n", "", "(estimate)", "defaults", "highest",
              "(pass timers)", "budget");
  json["budgets"] = nlohmann::json::array();
  for (const Budget& b : kBudgets) {
    double estimate = 0.0, measured = 0.0;
    bool present = false;
    // llvmpipe: the passes' timers (the pass table's), a feature's steps timed with its pass
    // (the volume caustics with the object caustics), each local light's apart ("<pass> [light
    // i]").
    for (const auto& [name, pass] : passes)
      for (const std::string& group : b.groups)
        if (name == group || name.rfind(group + " [", 0) == 0) measured += pass.measured;
    // The reference class's estimate: the step table's sums per feature, not estimated again.
    for (const std::string& group : b.groups) {
      const auto sums = featureMs.find(group);
      if (sums == featureMs.end()) continue;
      present = true;
      if (reference != gpus.end()) estimate += sums->second[reference - gpus.begin()];
    }
    if (!present) continue;
    const double ratio = floorMs > 0.0 ? measured / floorMs : 0.0;
    auto mark = [](bool applies, bool ok) { return !applies ? "" : ok ? "yes" : "no"; };
    const bool gpu = b.gpu && reference != gpus.end();
    char ratioBudget[16] = "";
    if (b.llvmpipeRatio > 0.0)
      std::snprintf(ratioBudget, sizeof(ratioBudget), "%s %g",
                    ratio <= b.llvmpipeRatio ? "<=" : ">", b.llvmpipeRatio);
    char estimateText[16] = "";
    if (gpu) std::snprintf(estimateText, sizeof(estimateText), "%.4f", estimate);
    std::printf("%-48s %12s %9s %9s %14.1f %9s\n", b.feature, estimateText,
                mark(gpu, estimate <= kDefaultBudgetMs), mark(gpu, estimate <= kHighestBudgetMs),
                ratio, ratioBudget);
    nlohmann::json row = {{"feature", b.feature}, {"llvmpipe_floor_ratio", ratio}};
    if (gpu) {
      row["rtx3060_ms"] = estimate;
      row["within_default_budget"] = estimate <= kDefaultBudgetMs;
      row["within_highest_budget"] = estimate <= kHighestBudgetMs;
    }
    if (b.llvmpipeRatio > 0.0) row["llvmpipe_ratio_budget"] = b.llvmpipeRatio;
    json["budgets"].push_back(row);
  }
  // The passes' timer queries against the CPU's clock around the whole dispatch (its own
  // bookkeeping included): how far llvmpipe's GL_TIME_ELAPSED can be trusted here.
  double timed = floorMs;
  for (const std::string& name : passOrder) timed += passes[name].measured;
  std::vector<double> wall(m.wallMs.end() - std::min<std::ptrdiff_t>(m.wallMs.size(), 16),
                           m.wallMs.end());
  std::sort(wall.begin(), wall.end());
  const double wallMedian = wall.empty() ? 0.0 : wall[wall.size() / 2];
  std::printf("%-32s %s %12.3f   (the passes' timers sum to %.3f)\n", "dispatch, CPU clock",
              std::string(12 * gpus.size(), ' ').c_str(), wallMedian, timed);
  json["llvmpipe_dispatch_wall_ms"] = wallMedian;
  json["llvmpipe_passes_timed_ms"] = timed;
  if (m.calibrated) {
    std::printf("\nthis machine's llvmpipe, measured one kind of work at a time:\n%s",
                m.cpu.describe().c_str());
    json["llvmpipe_class"] = {{"fragment_lane_ns", m.cpu.fragmentLane * 1e9},
                              {"alu_op_ns", m.cpu.aluOp * 1e9},
                              {"transcendental_ns", m.cpu.transcendental * 1e9},
                              {"division_ns", m.cpu.division * 1e9},
                              {"fetch_ns", m.cpu.fetch * 1e9},
                              {"vertex_ns", m.cpu.vertex * 1e9},
                              {"compute_invocation_ns", m.cpu.computeInvocation * 1e9},
                              {"primitive_ns", m.cpu.primitive * 1e9},
                              {"blended_byte_ns", m.cpu.blendedByte * 1e9},
                              {"atomic_ns", m.cpu.atomic * 1e9},
                              {"buffer_byte_ns", m.cpu.bufferByte * 1e9},
                              {"cleared_byte_ns", m.cpu.clearedByte * 1e9},
                              {"call_us", m.cpu.call * 1e6}};
  }
  return options.json.empty() ? 0 : writeResultFile(options.json, json.dump(2));
}

}  // namespace ocean
