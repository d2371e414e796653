#pragma once
// What a measurement names as its origin: the code revision that was built and the day it ran.
#include <string>

namespace ocean::report {

// `git describe --always --dirty` of the source tree at build time, "unknown" without git.
std::string sourceRevision();
// Today in UTC, YYYY-MM-DD.
std::string utcDate();

}  // namespace ocean::report
