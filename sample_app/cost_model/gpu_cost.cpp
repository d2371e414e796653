#include "gpu_cost.h"

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

namespace ocean::cost {

extern const char kGpuClassesJson[];  // gpu_classes.json, compiled in (CMakeLists.txt)

namespace {

// A figure of a class: its "value" (its "source" or "assumption" is for the reader).
bool figure(const nlohmann::json& entry, const char* key, double& out, std::string& error) {
  const auto it = entry.find(key);
  if (it == entry.end() || !it->is_object() || !it->contains("value") ||
      !(*it)["value"].is_number() || !(it->contains("source") || it->contains("assumption"))) {
    error = std::string("gpu classes: '") + key +
            "' needs a number 'value' and a 'source' or "
            "'assumption'";
    return false;
  }
  out = (*it)["value"].get<double>();
  if (!(out > 0.0) || !std::isfinite(out)) {
    error = std::string("gpu classes: '") + key + "' must be positive";
    return false;
  }
  return true;
}

}  // namespace

bool parseGpuClasses(std::string_view text, std::vector<GpuClass>& out, std::string& error) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.contains("classes") || !json["classes"].is_array()) {
    error = "gpu classes: not a JSON object with a 'classes' array";
    return false;
  }
  std::vector<GpuClass> classes;
  for (const nlohmann::json& entry : json["classes"]) {
    GpuClass c;
    if (!entry.is_object() || !entry.contains("name") || !entry["name"].is_string()) {
      error = "gpu classes: a class without a 'name'";
      return false;
    }
    c.name = entry["name"].get<std::string>();
    c.label = entry.value("label", c.name);
    double clockMhz = 0.0, bandwidthGbs = 0.0, l2Mb = 0.0, barrierUs = 0.0;
    if (!figure(entry, "clock_mhz", clockMhz, error) ||
        !figure(entry, "fp32_lanes", c.fp32Lanes, error) ||
        !figure(entry, "sfu_lanes", c.sfuLanes, error) || !figure(entry, "tmus", c.tmus, error) ||
        !figure(entry, "rops", c.rops, error) ||
        !figure(entry, "raster_engines", c.rasterEngines, error) ||
        !figure(entry, "bandwidth_gbs", bandwidthGbs, error) ||
        !figure(entry, "l2_mb", l2Mb, error) ||
        !figure(entry, "atomics_per_clock", c.atomicsPerClock, error) ||
        !figure(entry, "barrier_us", barrierUs, error)) {
      error += " (class " + c.name + ")";
      return false;
    }
    c.clockHz = clockMhz * 1e6;
    c.bandwidth = bandwidthGbs * 1e9;
    c.l2Bytes = l2Mb * 1024.0 * 1024.0;
    c.barrierSeconds = barrierUs * 1e-6;
    classes.push_back(c);
  }
  out = std::move(classes);
  return true;
}

bool gpuClasses(std::vector<GpuClass>& out, std::string& error) {
  return parseGpuClasses(kGpuClassesJson, out, error);
}

bool selectGpuClasses(std::string_view names, std::vector<GpuClass>& out, std::string& error) {
  std::vector<GpuClass> all;
  if (!gpuClasses(all, error)) return false;
  if (names == "all") {
    out = all;
    return true;
  }
  out.clear();
  while (!names.empty()) {
    const std::size_t comma = names.find(',');
    const std::string_view name = names.substr(0, comma);
    names = comma == std::string_view::npos ? std::string_view() : names.substr(comma + 1);
    const auto it =
        std::find_if(all.begin(), all.end(), [&](const GpuClass& c) { return c.name == name; });
    if (it == all.end()) {
      std::string known;
      for (const GpuClass& c : all) known += (known.empty() ? "" : ", ") + c.name;
      error = "--gpu: unknown class '" + std::string(name) + "' (known: " + known + ", all)";
      return false;
    }
    out.push_back(*it);
  }
  if (out.empty()) {
    error = "--gpu: no class named";
    return false;
  }
  return true;
}

double fragmentLanes(double fragments, double primitives) {
  if (!(fragments > 0.0)) return 0.0;
  if (!(primitives > 0.0)) return fragments;
  const double a = fragments / primitives;
  if (a <= 1.0) return 4.0 * fragments;
  const double side = std::sqrt(a) + 1.0;
  return fragments * side * side / a;
}

StepEstimate estimate(const postfx::WorkStep& step, const StepAlu& alu, const GpuClass& gpu) {
  const postfx::WorkCounts& w = step.work;
  StepEstimate e;
  const double lanes = fragmentLanes(double(w.fragments), double(w.primitives));
  const double perLane = w.fragments > 0 ? lanes / double(w.fragments) : 1.0;
  const double invocations = lanes + double(w.vertices) + double(w.computeInvocations);
  // Special functions on their own units (a division is a reciprocal there, and a multiply).
  const double sfu = alu.fragment.special() * lanes + alu.vertex.special() * double(w.vertices) +
                     alu.compute.special() * double(w.computeInvocations);
  e.shading =
      (alu.fragment.gpuOps * lanes + alu.vertex.gpuOps * double(w.vertices) +
       alu.compute.gpuOps * double(w.computeInvocations) + kInvocationOverhead * invocations) /
          (gpu.fp32Lanes * gpu.clockHz) +
      sfu / (gpu.sfuLanes * gpu.clockHz);
  const double fetches =
      double(w.fragmentFetches) * perLane + double(w.fetches - w.fragmentFetches);
  e.texture = fetches / (gpu.tmus * gpu.clockHz);
  e.memory = double(w.bytesRead + w.bytesWritten) / gpu.bandwidth;
  e.raster = double(w.primitives) / (gpu.rasterEngines * gpu.clockHz);
  // GF100 on: a ROP writes 4 bytes of a sample per clock (RGBA8 1, RGBA16F 2, RGBA32F 4 clocks).
  const double ropClocks = std::max(1.0, double(step.targetBytes) / 4.0);
  e.rop =
      double(w.samplesPassed) * (step.targetBytes > 0 ? ropClocks : 0.0) / (gpu.rops * gpu.clockHz);
  e.atomics = double(w.atomics) / (gpu.atomicsPerClock * gpu.clockHz);
  e.overhead = double(w.draws + w.dispatches) * gpu.barrierSeconds;
  const std::pair<double, const char*> terms[] = {{e.shading, "shading"}, {e.texture, "texture"},
                                                  {e.memory, "memory"},   {e.raster, "raster"},
                                                  {e.rop, "rop"},         {e.atomics, "atomics"}};
  const auto* top =
      std::max_element(std::begin(terms), std::end(terms),
                       [](const auto& a, const auto& b) { return a.first < b.first; });
  e.seconds = top->first + e.overhead;
  e.bound = top->first > 0.0 ? top->second : "overhead";
  return e;
}

postfx::WorkStep atViewSize(const postfx::WorkStep& step, double fromPixels, double toPixels) {
  if (step.work.draws == 0 || !(fromPixels > 0.0) || step.viewportPixels == 0) return step;
  // The view's own size, or a reduced pass's (a half or a quarter of each side), within rounding.
  const double share = double(step.viewportPixels) / fromPixels;
  bool perPixel = false;
  for (double reduced : {1.0, 0.25, 0.0625})
    perPixel = perPixel || std::abs(share - reduced) <= 0.05 * reduced;
  if (!perPixel) return step;
  const double k = toPixels / fromPixels;
  auto scaled = [k](std::uint64_t n) { return static_cast<std::uint64_t>(double(n) * k + 0.5); };
  postfx::WorkStep s = step;
  postfx::WorkCounts& w = s.work;
  const std::uint64_t otherFetches = w.fetches - w.fragmentFetches;
  w.fragments = scaled(w.fragments);
  w.samplesPassed = scaled(w.samplesPassed);
  w.blendedSamples = scaled(w.blendedSamples);
  w.fragmentFetches = scaled(w.fragmentFetches);
  w.fetches = otherFetches + w.fragmentFetches;
  w.bytesRead = scaled(w.bytesRead);
  w.bytesWritten = scaled(w.bytesWritten);
  s.viewportPixels = scaled(s.viewportPixels);
  return s;
}

}  // namespace ocean::cost
