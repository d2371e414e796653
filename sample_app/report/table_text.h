#pragma once
// Text the report's tables share: CSV quoting and writing a whole file atomically.
#include <string>

namespace ocean::report {

// `text` as one CSV field: quoted (inner quotes doubled) only when it holds a comma, a quote or
// a line break.
std::string csvField(const std::string& text);

// Writes `text` to `path` through a temporary file, so that a reader never sees half a table.
bool writeText(const std::string& path, const std::string& text, std::string& error);

}  // namespace ocean::report
