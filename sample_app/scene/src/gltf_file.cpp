#include "gltf_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace ocean_scene::gltf {

namespace {

// Why a non-regular file is refused; "" for a regular file.
std::string notRegularReason(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

// Closes the descriptor on every path out of readRegularFile.
struct Descriptor {
  int fd = -1;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

bool hasScheme(const std::string& uri) {
  // RFC 3986: ALPHA *( ALPHA / DIGIT / "+" / "-" / "." ) ":" before any '/', '?' or '#'.
  if (uri.empty() || !std::isalpha(static_cast<unsigned char>(uri[0]))) return false;
  for (char c : uri) {
    if (c == ':') return true;
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '+' && c != '-' && c != '.') {
      return false;
    }
  }
  return false;
}

}  // namespace

bool readRegularFile(const std::string& path, std::uint64_t maxBytes,
                     std::vector<unsigned char>& bytes, std::string& error) {
  struct stat before {};
  if (::stat(path.c_str(), &before) != 0) {
    error = std::string("cannot open file: ") + std::strerror(errno);
    return false;
  }
  if (const std::string reason = notRegularReason(before.st_mode); !reason.empty()) {
    error = reason;
    return false;
  }
  Descriptor file;
  file.fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (file.fd < 0) {
    error = std::string("cannot open file: ") + std::strerror(errno);
    return false;
  }
  struct stat opened {};
  if (::fstat(file.fd, &opened) != 0) {
    error = std::string("cannot read file status: ") + std::strerror(errno);
    return false;
  }
  if (const std::string reason = notRegularReason(opened.st_mode); !reason.empty()) {
    error = reason;
    return false;
  }
  if (opened.st_size == 0) {
    error = "file is empty";
    return false;
  }
  const auto size = static_cast<std::uint64_t>(opened.st_size);
  if (size > maxBytes) {
    error = "file is larger than " + std::to_string(maxBytes >> 20) + " MiB";
    return false;
  }
  bytes.resize(static_cast<std::size_t>(size));
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t got = ::read(file.fd, bytes.data() + done, bytes.size() - done);
    if (got < 0 && errno == EINTR) continue;
    if (got <= 0) {
      error = got == 0 ? "file shrank while it was read"
                       : std::string("read failed: ") + std::strerror(errno);
      bytes.clear();
      return false;
    }
    done += static_cast<std::size_t>(got);
  }
  return true;
}

std::string decodeUri(const std::string& uri) {
  const auto hex = [](char c) -> int {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;  // as tinygltf: a bad digit counts as 0
  };
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '+') {
      out += ' ';
    } else if (uri[i] == '%' && uri.size() > i + 2) {
      out += static_cast<char>((hex(uri[i + 1]) << 4) | hex(uri[i + 2]));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

std::string realFolder(const std::string& folder) {
  char buffer[PATH_MAX];
  if (::realpath(folder.c_str(), buffer) == nullptr) return "";
  return buffer;
}

bool resolveInFolder(const std::string& folder, const std::string& rawUri,
                     const std::string& decodedUri, std::string& resolved, std::string& error) {
  if (decodedUri.empty()) {
    error = "is empty";
    return false;
  }
  if (hasScheme(rawUri) || hasScheme(decodedUri)) {
    error = "is a URL with a scheme (" + rawUri.substr(0, rawUri.find(':') + 1) +
            "); only relative paths inside the model's folder are read";
    return false;
  }
  if (decodedUri.find('\0') != std::string::npos) {
    error = "contains a NUL byte";
    return false;
  }
  if (decodedUri[0] == '/' || decodedUri[0] == '\\') {
    error = "is an absolute path; only relative paths inside the model's folder are read";
    return false;
  }
  // Resolved lexically, as a URI reference is (RFC 3986 5.2.4): "." segments and empty ones
  // drop out and ".." takes back the segment before it, so "sub/../a.bin" is "a.bin" whether
  // or not "sub" exists (or is a link that leads elsewhere). A ".." with nothing left to take
  // back leaves the folder. Backslashes separate segments too, as exporters on Windows write.
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (start <= decodedUri.size()) {
    std::size_t end = decodedUri.find_first_of("/\\", start);
    if (end == std::string::npos) end = decodedUri.size();
    const std::string segment = decodedUri.substr(start, end - start);
    if (segment == "..") {
      if (segments.empty()) {
        error = "leaves the model's folder ('..' above it); only paths inside it are read";
        return false;
      }
      segments.pop_back();
    } else if (!segment.empty() && segment != ".") {
      segments.push_back(segment);
    }
    start = end + 1;
  }
  if (segments.empty()) {
    error = "names the model's folder itself, not a file in it";
    return false;
  }
  if (folder.empty()) {
    error = "cannot be resolved: the model's folder is not accessible";
    return false;
  }
  std::string joined = folder;
  for (const std::string& segment : segments) joined += "/" + segment;
  char buffer[PATH_MAX];
  if (::realpath(joined.c_str(), buffer) == nullptr) {
    error = "names no file in the model's folder";
    return false;
  }
  // Lexically inside, so only a symbolic link on the way can have led out.
  const std::string real = buffer;
  if (real.compare(0, folder.size() + 1, folder + "/") != 0) {
    error = real == folder ? "names the model's folder itself, not a file in it"
                           : "is a symbolic link that leads out of the model's folder";
    return false;
  }
  struct stat status {};
  if (::stat(real.c_str(), &status) != 0) {
    error = "names no readable file in the model's folder";
    return false;
  }
  if (const std::string reason = notRegularReason(status.st_mode); !reason.empty()) {
    error = reason;
    return false;
  }
  resolved = real;
  return true;
}

}  // namespace ocean_scene::gltf
