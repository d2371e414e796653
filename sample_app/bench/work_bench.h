#pragma once
// ocean_sample bench --work: the preset's frame rendered with the plugin's work account on
// (counted in its shaders), each step's work printed with its estimated time on the --gpu
// classes (cost_model/gpu_cost.h), beside each pass's llvmpipe time (timed without the account,
// with the benchmark floor) and what the CPU model (cost_model/cpu_cost.h) predicts of it.
// Writes --json too. Needs the session's GL context current.
#include "headless_session.h"
#include "options.h"

namespace ocean {

int runWorkBench(HeadlessSession& session, const Options& options);

}  // namespace ocean
