#pragma once
// This machine's CPU rasteriser measured one kind of work at a time (cost_model/cpu_cost.h):
// microbenchmarks that each isolate a fragment lane, an arithmetic instruction, a texture fetch,
// a vertex, a compute invocation, a primitive, a blended byte, an atomic, a cleared byte and a
// draw call, timed by the CPU's clock from a drained pipeline to a drained one (median of a few
// runs).
// The arithmetic of each program is read from Mesa's own dump of it (shader_statistics.h), so
// the per-instruction cost divides by what the driver really compiled. Needs a current GL 4.5
// context created after cost::requestMesaShaderDump().
#include <string>

#include "cpu_cost.h"

namespace ocean {

bool calibrateCpu(cost::CpuClass& out, std::string& error);

}  // namespace ocean
