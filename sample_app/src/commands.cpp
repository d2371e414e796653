#include "commands.h"

#include <cstdio>
#include <fstream>

namespace ocean {

int commandFailed(const std::string& message) {
  std::fprintf(stderr, "ocean_sample: %s\n", message.c_str());
  return 1;
}

int writeResultFile(const std::string& path, const std::string& text) {
  std::ofstream file(path);
  file << text << '\n';
  return file ? 0 : commandFailed("cannot write '" + path + "'");
}

}  // namespace ocean
