#include "shader_statistics.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <sstream>
#include <vector>

#include <nlohmann/json.hpp>

namespace ocean::cost {

namespace {

int dumpFile = -1;  // the memfd Mesa's log file names (requestMesaShaderDump)

// The dump file's size with Mesa's buffered writes flushed (its FILE is this process's libc's).
long long dumpSize() {
  std::fflush(nullptr);
  struct stat info {};
  return dumpFile >= 0 && fstat(dumpFile, &info) == 0 ? static_cast<long long>(info.st_size) : 0;
}

}  // namespace

void requestMesaShaderDump() {
  if (dumpFile < 0) dumpFile = memfd_create("ocean_shader_dump", 0);
  if (dumpFile >= 0) {
    // Mesa opens its log by name ("w") at its first message: this process's own descriptor.
    const std::string path =
        "/proc/" + std::to_string(getpid()) + "/fd/" + std::to_string(dumpFile);
    setenv("MESA_LOG_FILE", path.c_str(), 1);
  }
  setenv("MESA_GLSL", "dump", 1);
  setenv("MESA_SHADER_CACHE_DISABLE", "true", 1);
}

ShaderDumpCapture::ShaderDumpCapture() : start_(dumpSize()) {
  // What was printed before (the host's programs, instrumented ones) is not wanted: free it.
  if (start_ > 0) fallocate(dumpFile, FALLOC_FL_PUNCH_HOLE | FALLOC_FL_KEEP_SIZE, 0, start_);
}

std::string ShaderDumpCapture::text() {
  const long long end = dumpSize();
  std::string out;
  if (dumpFile < 0 || end <= start_) return out;
  out.resize(static_cast<std::size_t>(end - start_));
  std::size_t done = 0;
  while (done < out.size()) {
    const ssize_t n = pread(dumpFile, out.data() + done, out.size() - done, start_ + done);
    if (n <= 0) break;
    done += static_cast<std::size_t>(n);
  }
  out.resize(done);
  return out;
}

double StageStatistics::iterations(double fetches, double atomicOps) const {
  const double inLoops = loopTex + loopAtomics;
  return inLoops > 0.0 ? std::max(fetches + atomicOps - tex - atomics, 0.0) / inLoops : 1.0;
}

double StageStatistics::perInvocation(double fetches, double atomicOps) const {
  return present ? alu + loopAlu * iterations(fetches, atomicOps) : 0.0;
}

double StageStatistics::gpuPerInvocation(double fetches, double atomicOps) const {
  return present ? alu - free + (loopAlu - loopFree) * iterations(fetches, atomicOps) : 0.0;
}

double StageStatistics::transcendentalPerInvocation(double fetches, double atomicOps) const {
  return present ? transcendental + loopTranscendental * iterations(fetches, atomicOps) : 0.0;
}

double StageStatistics::divisionPerInvocation(double fetches, double atomicOps) const {
  return present ? division + loopDivision * iterations(fetches, atomicOps) : 0.0;
}

namespace {

// The instruction of a NIR line "vecN B ssa_k = op ...": its components and opcode.
// A NIR line "vecN B ssa_k = op a, b": its result, components, opcode and operands' names.
bool instruction(const std::string& line, std::string& result, int& components, std::string& op,
                 std::vector<std::string>& operands) {
  std::istringstream in(line);
  std::string vec, bits, equals;
  if (!(in >> vec >> bits >> result >> equals) || equals != "=" || vec.rfind("vec", 0) != 0)
    return false;
  components = std::atoi(vec.c_str() + 3);
  in >> op;
  operands.clear();
  for (std::string token; in >> token;) {
    while (!token.empty() && (token.back() == ',' || token.back() == ')')) token.pop_back();
    const std::size_t at = token.find("ssa_");
    if (at != std::string::npos) operands.push_back(token.substr(at));
  }
  return !op.empty();
}

bool arithmetic(const std::string& op) {
  if (op == "load_const" || op == "undefined" || op == "intrinsic" || op == "phi" || op == "mov")
    return false;
  if (op.rfind("deref_", 0) == 0) return false;
  // vec2/vec3/vec4...: gathering components, a move.
  if (op.size() > 3 && op.rfind("vec", 0) == 0 && std::isdigit(static_cast<unsigned char>(op[3])))
    return false;
  return op[0] != '(';  // "(float32)txl ...": a texture instruction
}

bool among(const std::string& op, std::initializer_list<const char*> names) {
  for (const char* name : names)
    if (op == name) return true;
  return false;
}
bool transcendentalOp(const std::string& op) {
  return among(op, {"fexp2", "flog2", "fpow", "fsin", "fcos"});
}
bool divisionOp(const std::string& op) {
  return among(op, {"frcp", "frsq", "fsqrt", "fdiv", "idiv", "udiv", "imod", "umod", "irem"});
}

}  // namespace

std::map<GLuint, ProgramStatistics> parseNirDump(const std::string& text) {
  std::map<GLuint, ProgramStatistics> out;
  std::istringstream lines(text);
  std::string line;
  StageStatistics* stage = nullptr;
  std::string pendingStage;
  bool inMain = false;
  std::vector<bool> loops;  // open blocks inside main: is each a loop
  int loopDepth = 0;
  std::vector<std::string> operands;
  std::set<std::string> products;  // fmul results no fadd has fused yet
  while (std::getline(lines, line)) {
    if (line.rfind("shader: MESA_SHADER_", 0) == 0) {
      pendingStage = line.substr(20);
      stage = nullptr;
      inMain = false;
      continue;
    }
    if (line.rfind("name: GLSL", 0) == 0 && !pendingStage.empty()) {
      ProgramStatistics& p = out[GLuint(std::strtoul(line.c_str() + 10, nullptr, 10))];
      stage = pendingStage == "VERTEX"     ? &p.vertex
              : pendingStage == "FRAGMENT" ? &p.fragment
              : pendingStage == "COMPUTE"  ? &p.compute
                                           : nullptr;
      if (stage != nullptr) *stage = StageStatistics{};
      pendingStage.clear();
      continue;
    }
    if (stage == nullptr) continue;
    if (line == "impl main {") {
      inMain = true;
      stage->present = true;
      loops.clear();
      loopDepth = 0;
      products.clear();
      continue;
    }
    if (!inMain) continue;
    if (line == "}") {
      inMain = false;
      stage = nullptr;
      continue;
    }
    std::size_t first = line.find_first_not_of(" \t");
    if (first == std::string::npos) continue;
    const std::string body = line.substr(first);
    if (body.rfind('}', 0) == 0) {  // "}" or "} else {"
      if (!loops.empty()) {
        loopDepth -= loops.back() ? 1 : 0;
        loops.pop_back();
      }
      if (body.find('{') != std::string::npos) loops.push_back(false);
      continue;
    }
    if (!body.empty() && body.back() == '{') {
      const bool loop = body.rfind("loop", 0) == 0;
      loops.push_back(loop);
      loopDepth += loop ? 1 : 0;
      continue;
    }
    int components = 0;
    std::string result, op;
    if (!instruction(body, result, components, op, operands)) continue;
    const double n = std::max(components, 1);
    if (op == "intrinsic" && body.find("atomic") != std::string::npos) {
      (loopDepth > 0 ? stage->loopAtomics : stage->atomics) += 1.0;
    } else if (op[0] == '(') {
      (loopDepth > 0 ? stage->loopTex : stage->tex) += 1.0;
    } else if (arithmetic(op)) {
      const bool loop = loopDepth > 0;
      (loop ? stage->loopAlu : stage->alu) += n;
      if (transcendentalOp(op)) (loop ? stage->loopTranscendental : stage->transcendental) += n;
      if (divisionOp(op)) (loop ? stage->loopDivision : stage->division) += n;
      // What a GPU's compiler does not issue as instructions of their own: negation, absolute
      // value and saturation are operand modifiers there, and an add of a product it fuses
      // with that multiply (each product once).
      if (op == "fneg" || op == "fabs" || op == "fsat") {
        (loop ? stage->loopFree : stage->free) += n;
      } else if (op == "fmul") {
        products.insert(result);
      } else if (op == "fadd") {
        for (const std::string& operand : operands)
          if (products.erase(operand) > 0) {
            (loop ? stage->loopFree : stage->free) += n;
            break;
          }
      }
    }
  }
  return out;
}

std::string programLabel(GLuint program) {
  if (program == 0 || glIsProgram(program) != GL_TRUE) return "";
  char label[256] = {};
  GLsizei length = 0;
  glGetObjectLabel(GL_PROGRAM, program, sizeof(label), &length, label);
  return std::string(label, size_t(std::max(length, 0)));
}

std::map<std::string, ProgramStatistics> labelled(
    const std::map<GLuint, ProgramStatistics>& byName) {
  std::map<std::string, ProgramStatistics> out;
  for (const auto& [name, statistics] : byName) {
    const std::string label = programLabel(name);
    if (!label.empty()) out[label] = statistics;
  }
  return out;
}

StepAlu stepAlu(const ProgramStatistics& p, const postfx::WorkCounts& w) {
  auto per = [](std::uint64_t n, std::uint64_t of) {
    return of > 0 ? double(n) / double(of) : 0.0;
  };
  auto stage = [](const StageStatistics& s, double fetches, double atomics) {
    return StageAlu{s.perInvocation(fetches, atomics), s.gpuPerInvocation(fetches, atomics),
                    s.transcendentalPerInvocation(fetches, atomics),
                    s.divisionPerInvocation(fetches, atomics)};
  };
  StepAlu a;
  // The account keeps the atomics of all stages together: a draw's are its fragments' (the
  // only stage of ours with any).
  if (w.computeInvocations > 0) {
    a.compute = stage(p.compute, per(w.fetches, w.computeInvocations),
                      per(w.atomics, w.computeInvocations));
    return a;
  }
  // Every fragment is charged the full path (a SIMD group runs it while any of its lanes does,
  // discarded or not: measured on llvmpipe, docs/gpu_cost.md), its loops run as many times as
  // the writing fragments' fetches and atomics say (the discarded ones' taken as none).
  const bool samples = (w.sources & postfx::kWorkFromSamplesPassed) != 0;
  const std::uint64_t writing = samples ? std::min(w.samplesPassed, w.fragments) : w.fragments;
  a.fragment = stage(p.fragment, per(w.fragmentFetches, writing), per(w.atomics, writing));
  a.vertex = stage(p.vertex, per(w.fetches - w.fragmentFetches, w.vertices), 0.0);
  return a;
}

namespace {

// Every field of a stage, by name: one list for both directions.
template <typename Stage, typename Visit>
void fields(Stage& s, Visit&& visit) {
  visit("alu", s.alu);
  visit("loop_alu", s.loopAlu);
  visit("transcendental", s.transcendental);
  visit("loop_transcendental", s.loopTranscendental);
  visit("division", s.division);
  visit("loop_division", s.loopDivision);
  visit("free", s.free);
  visit("loop_free", s.loopFree);
  visit("tex", s.tex);
  visit("loop_tex", s.loopTex);
  visit("atomics", s.atomics);
  visit("loop_atomics", s.loopAtomics);
}

}  // namespace

std::string writeStatistics(const std::map<std::string, ProgramStatistics>& programs) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& [label, p] : programs) {
    nlohmann::json& entry = json[label];
    for (const auto& [name, stage] :
         {std::pair{"vertex", &p.vertex}, std::pair{"fragment", &p.fragment},
          std::pair{"compute", &p.compute}}) {
      if (!stage->present) continue;
      nlohmann::json values;
      fields(*stage, [&](const char* key, double v) { values[key] = v; });
      entry[name] = values;
    }
  }
  return json.dump(1);
}

bool readStatistics(const std::string& text, std::map<std::string, ProgramStatistics>& programs,
                    std::string& error) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (json.is_discarded() || !json.is_object()) {
    error = "program statistics: not a JSON object";
    return false;
  }
  std::map<std::string, ProgramStatistics> out;
  for (const auto& [label, entry] : json.items()) {
    ProgramStatistics& p = out[label];
    for (const auto& [name, stage] :
         {std::pair{"vertex", &p.vertex}, std::pair{"fragment", &p.fragment},
          std::pair{"compute", &p.compute}}) {
      if (!entry.contains(name)) continue;
      const nlohmann::json& values = entry[name];
      stage->present = true;
      bool ok = true;
      fields(*stage, [&](const char* key, double& v) {
        if (values.contains(key) && values[key].is_number())
          v = values[key].get<double>();
        else
          ok = false;
      });
      if (!ok) {
        error = "program statistics: " + label + "." + name + " lacks a field";
        return false;
      }
    }
  }
  programs = std::move(out);
  return true;
}

std::array<double, postfx::kPassCount> passEstimatesMs(
    const postfx::WorkSteps& steps, const std::map<std::string, ProgramStatistics>& programs,
    const GpuClass& gpu, double fromPixels, double toPixels) {
  std::array<double, postfx::kPassCount> ms{};
  for (int i = 0; i < steps.count; ++i) {
    const postfx::WorkStep& s = steps.steps[i];
    const auto p = programs.find(programLabel(s.program));
    const StepAlu alu = p == programs.end() ? StepAlu{} : stepAlu(p->second, s.work);
    ms[static_cast<int>(s.pass)] +=
        estimate(atViewSize(s, fromPixels, toPixels), alu, gpu).seconds * 1e3;
  }
  return ms;
}

}  // namespace ocean::cost
