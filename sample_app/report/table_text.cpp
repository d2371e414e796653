#include "table_text.h"

#include <fstream>

#include <atomic_file.h>

namespace ocean::report {

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

bool writeText(const std::string& path, const std::string& text, std::string& error) {
  return writeThroughTemporary(
      path,
      [&](const std::string& temporary, std::string& why) {
        std::ofstream file(temporary, std::ios::binary);
        file << text;
        file.close();
        if (!file) why = "cannot write '" + path + "'";
        return bool(file);
      },
      error);
}

}  // namespace ocean::report
