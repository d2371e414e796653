#pragma once
// The sub-commands of ocean_sample. Each returns the process exit code and writes nothing but
// its result (and one error line on stderr) .
#include "options.h"

namespace ocean {

int runRender(const Options& options);
int runView(const Options& options);
int runBench(const Options& options);
int runReport(const Options& options);

}  // namespace ocean
