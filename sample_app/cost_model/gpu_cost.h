#pragma once
// The GPU cost model (docs/gpu_cost.md): a step of the plugin's work account (postfx/
// diagnostics.h: WorkStep) turned into an estimated time on a GPU class, roofline-style. Each of
// the step's demands is divided by the rate the class serves it at; the largest is the step's
// time, plus a fixed cost per dependent draw or dispatch:
//   shading   invocations (fragment lanes) x (ALU ops + overhead) / (FP32 lanes x clock),
//             plus their special functions / (SFU lanes x clock)
//   texture   fetches (fragment fetches once per lane) / (TMUs x clock)
//   memory    bytes read and written at least once / DRAM bandwidth
//   raster    primitives / (raster engines x clock), one triangle per clock each
//   ROP       samples written x (1, 2 or 4 clocks by target bytes) / (ROPs x clock)
//   atomics   atomics / (atomics per clock x clock)
// Fragment lanes: fragments are shaded in 2 x 2 quads; a primitive of a pixels (fragments per
// primitive) shades about (sqrt(a) + 1)^2 lanes, 4 per fragment for a <= 1.
// An estimate, never a measurement: every number it prints says so.
#include <postfx/diagnostics.h>

#include <string>
#include <string_view>
#include <vector>

namespace ocean::cost {

// One GPU class of gpu_classes.json: unit counts and clocks, each with its source there.
struct GpuClass {
  std::string name, label;
  double clockHz = 0.0;
  double fp32Lanes = 0.0, sfuLanes = 0.0, tmus = 0.0, rops = 0.0, rasterEngines = 0.0;
  double bandwidth = 0.0;  // bytes/s
  double l2Bytes = 0.0;
  double atomicsPerClock = 0.0;
  double barrierSeconds = 0.0;  // per dependent draw or dispatch
};

// The classes of the table compiled in (gpu_classes.json); false with `error` on a malformed one.
bool gpuClasses(std::vector<GpuClass>& out, std::string& error);
bool parseGpuClasses(std::string_view json, std::vector<GpuClass>& out, std::string& error);
// The classes named in `names` (comma-separated, or "all"); false naming an unknown one.
bool selectGpuClasses(std::string_view names, std::vector<GpuClass>& out, std::string& error);

// Instructions every invocation costs beyond its stated ALU ops (launch, interpolation or
// indexing, export); docs/gpu_cost.md says why this value.
inline constexpr double kInvocationOverhead = 8.0;

// Shaded fragment lanes of `fragments` from `primitives` (2 x 2 quads).
double fragmentLanes(double fragments, double primitives);

struct StepEstimate {
  double shading = 0.0, texture = 0.0, memory = 0.0, raster = 0.0, rop = 0.0, atomics = 0.0;
  double overhead = 0.0;   // the dependent draws' and dispatches' fixed cost
  double seconds = 0.0;    // the largest term plus the overhead
  const char* bound = "";  // the largest term's name
};
// A stage's arithmetic per invocation (shader_statistics.h), scalar instructions, and of those
// the special functions: transcendental (exp2, log2, pow, sine, cosine) and divisions and roots.
struct StageAlu {
  double ops = 0.0;     // as the driver compiled it (Mesa's NIR)
  double gpuOps = 0.0;  // as a GPU issues it: modifiers and fused multiply-adds taken out
  double transcendental = 0.0, division = 0.0;
  double special() const { return transcendental + division; }
};
struct StepAlu {
  StageAlu vertex, fragment, compute;
};
StepEstimate estimate(const postfx::WorkStep& step, const StepAlu& alu, const GpuClass& gpu);

// `step` as it would be on a view of `toPixels` rather than `fromPixels`: a draw over the view
// (or a half or quarter of each side of it, a reduced-resolution pass) has its fragments,
// samples, fragment fetches and bytes scaled by their ratio; the rest (pre-passes over the
// water's tiles, grids, caster maps, dispatches) is what it was.
postfx::WorkStep atViewSize(const postfx::WorkStep& step, double fromPixels, double toPixels);

}  // namespace ocean::cost
