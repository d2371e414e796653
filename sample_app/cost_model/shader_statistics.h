#pragma once
// The plugin's shaders' arithmetic, as the driver compiled them: Mesa prints each linked
// program's final NIR (MESA_GLSL=dump), the intermediate form its GPU and CPU back ends compile
// from, so the scalar instructions of each stage can be counted, inside and outside loops. The
// work account counts invocations and fetches; this supplies the arithmetic per invocation that
// the cost models charge for (docs/gpu_cost.md). Mesa only: elsewhere nothing is captured and
// the models charge the invocation overhead alone.
#include <epoxy/gl.h>

#include <array>
#include <map>
#include <string>

#include "gpu_cost.h"

namespace ocean::cost {

// Asks Mesa to print every program it links (and not to take them from its disk cache, which
// would skip the compile) into an anonymous in-memory file (MESA_LOG_FILE), never on stderr.
// Call before the GL context is created; once per process.
void requestMesaShaderDump();

// The programs Mesa printed while this lives: text() returns what was written since it was
// made (empty without requestMesaShaderDump). What nothing captures is dropped: each capture
// frees what came before it.
class ShaderDumpCapture {
 public:
  ShaderDumpCapture();
  ShaderDumpCapture(const ShaderDumpCapture&) = delete;
  ShaderDumpCapture& operator=(const ShaderDumpCapture&) = delete;
  std::string text();

 private:
  long long start_ = 0;
};

// One stage's scalar instructions (a vecN instruction counts N): arithmetic, texture and atomic
// instructions outside loops and inside them (every level of nesting together).
struct StageStatistics {
  double alu = 0.0, loopAlu = 0.0;
  // Of the arithmetic, the special functions a GPU runs at a lower rate on its own units and a
  // CPU expands into many instructions: the transcendental ones (exp2, log2, pow, sine, cosine)
  // and divisions and roots (division, reciprocal, (inverse) square root, integer division).
  double transcendental = 0.0, loopTranscendental = 0.0;
  double division = 0.0, loopDivision = 0.0;
  // Of the arithmetic, what a GPU's compiler folds into other instructions: negation, absolute
  // value and saturation (operand modifiers) and each add of a product (fused multiply-add).
  double free = 0.0, loopFree = 0.0;
  double tex = 0.0, loopTex = 0.0;
  double atomics = 0.0, loopAtomics = 0.0;
  bool present = false;
  // The loops' iterations per invocation for `fetches` texture fetches and `atomics` atomics
  // per invocation (counted): how many times their fetches and atomics ran, 1 where a loop has
  // neither.
  double iterations(double fetches, double atomics) const;
  // Per invocation: arithmetic (special functions included), transcendental functions,
  // divisions. Both arms of every branch count: the full path, as a GPU warp that diverges runs
  // it.
  double perInvocation(double fetches, double atomics) const;
  double gpuPerInvocation(double fetches, double atomics) const;  // without what is free there
  double transcendentalPerInvocation(double fetches, double atomics) const;
  double divisionPerInvocation(double fetches, double atomics) const;
};
struct ProgramStatistics {
  StageStatistics vertex, fragment, compute;
};

// Parses Mesa's NIR dump: per GL program name ("name: GLSL<n>"), its stages.
std::map<GLuint, ProgramStatistics> parseNirDump(const std::string& text);

// The same keyed by each program's debug label (glGetObjectLabel, e.g. "postfx.caustics"),
// for the programs the current GL context still has; unlabelled ones are left out.
std::map<std::string, ProgramStatistics> labelled(
    const std::map<GLuint, ProgramStatistics>& byName);

// A GL program's debug label, "" without one.
std::string programLabel(GLuint program);

// A step's arithmetic per invocation from its program's statistics and its counted fetches.
StepAlu stepAlu(const ProgramStatistics& program, const postfx::WorkCounts& work);

// Each pass's estimated time (ms, indexed by postfx::Pass) on `gpu`: the sum of its steps, each
// with its program's arithmetic (by label) and scaled from a view of `fromPixels` to `toPixels`
// (atViewSize).
std::array<double, postfx::kPassCount> passEstimatesMs(
    const postfx::WorkSteps& steps, const std::map<std::string, ProgramStatistics>& programs,
    const GpuClass& gpu, double fromPixels, double toPixels);

// The statistics by label as JSON text and back, so that a machine without Mesa (a GPU's driver
// prints no NIR) estimates with what llvmpipe compiled of the same programs
// (sample_app/bench/standalone/gpu_bench.sh). read: false with `error` on malformed text.
std::string writeStatistics(const std::map<std::string, ProgramStatistics>& programs);
bool readStatistics(const std::string& text, std::map<std::string, ProgramStatistics>& programs,
                    std::string& error);

}  // namespace ocean::cost
