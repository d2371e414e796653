#pragma once
// Every file ocean_sample writes goes through here: the content is written to a hidden temporary
// name in the same directory and renamed into place only when complete, so a failed write
// leaves no file, and never half a file, behind.
#include <functional>
#include <string>

namespace ocean {

// The hidden temporary `path` is written through (same directory and extension).
std::string temporaryPathFor(const std::string& path);

// Creates and removes that temporary, so that a directory that refuses new files (read-only,
// /proc, no permission even for root) is found before any work; false with `error` naming
// `path` and the system's reason.
bool probeWritable(const std::string& path, std::string& error);

// `write` fills the file at the temporary path it is given (keeping `path`'s extension, so
// writers that pick a format by extension still do) and returns false with `error` set on
// failure; the temporary is then removed.
bool writeThroughTemporary(
    const std::string& path,
    const std::function<bool(const std::string& temporary, std::string& error)>& write,
    std::string& error);

}  // namespace ocean
