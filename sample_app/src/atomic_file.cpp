#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace ocean {

std::string temporaryPathFor(const std::string& path) {
  const std::filesystem::path target(path);
  // Appending (rather than chaining operator+) also sidesteps a GCC 12 -Wrestrict false positive.
  std::string temporaryName = ".";
  temporaryName += target.filename().string();
  temporaryName += ".partial";
  temporaryName += target.extension().string();
  return (target.parent_path() / temporaryName).string();
}

bool probeWritable(const std::string& path, std::string& error) {
  const std::string temporary = temporaryPathFor(path);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0600);
  if (fd < 0) {
    error = "cannot create '" + path + "': " + std::strerror(errno);
    return false;
  }
  ::close(fd);
  ::unlink(temporary.c_str());
  return true;
}

bool writeThroughTemporary(
    const std::string& path,
    const std::function<bool(const std::string& temporary, std::string& error)>& write,
    std::string& error) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  const fs::path temporary = temporaryPathFor(path);
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
