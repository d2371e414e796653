#include "atomic_file.h"

#include <filesystem>
#include <system_error>

namespace ocean {

bool writeThroughTemporary(
    const std::string& path,
    const std::function<bool(const std::string& temporary, std::string& error)>& write,
    std::string& error) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  // Appending (rather than chaining operator+) also sidesteps a GCC 12 -Wrestrict false positive.
  std::string temporaryName = ".";
  temporaryName += target.filename().string();
  temporaryName += ".partial";
  temporaryName += target.extension().string();
  const fs::path temporary = target.parent_path() / temporaryName;
  std::error_code code;
  if (!write(temporary.string(), error)) {
    fs::remove(temporary, code);
    return false;
  }
  fs::rename(temporary, target, code);
  if (code) {
    error = "cannot write '" + path + "': " + code.message();
    fs::remove(temporary, code);
    return false;
  }
  return true;
}

}  // namespace ocean
