#include "commands.h"

#include <cstdio>

namespace ocean {

int commandFailed(const std::string& message) {
  std::fprintf(stderr, "ocean_sample: %s\n", message.c_str());
  return 1;
}

}  // namespace ocean
