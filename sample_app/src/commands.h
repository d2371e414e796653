#pragma once
// The sub-commands of ocean_sample. Each returns the process exit code and writes nothing but
// its result (and one error line on stderr) .
#include <string>

#include "options.h"

namespace ocean {

// The one error line every command writes: "ocean_sample: <message>" on stderr. Returns 1.
int commandFailed(const std::string& message);
// Writes `text` and a newline to `path` (a command's --json): 0, or commandFailed's 1 naming it.
int writeResultFile(const std::string& path, const std::string& text);

int runRender(const Options& options);
// render --views N > 1, --stereo or --cube-map: several views of one frame in one plugin dispatch.
int runRenderViews(const Options& options);
int runView(const Options& options);
int runBench(const Options& options);
int runReport(const Options& options);
int runReference(const Options& options);
int runCompare(const Options& options);

}  // namespace ocean
