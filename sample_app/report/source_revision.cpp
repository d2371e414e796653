#include "source_revision.h"

#include <ctime>

#include "generated/source_revision.h"

namespace ocean::report {

std::string sourceRevision() {
  return OCEAN_SOURCE_REVISION;
}

std::string utcDate() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[16];
  std::strftime(text, sizeof(text), "%Y-%m-%d", &utc);
  return text;
}

}  // namespace ocean::report
