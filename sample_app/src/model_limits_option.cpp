#include "model_limits_option.h"

#include <charconv>

namespace ocean {

namespace {

// N with an optional k/M/G (x 1024^n) suffix, in [1, kMaxModelLimit].
bool parseCount(std::string_view text, std::uint64_t& value) {
  std::uint64_t scale = 1;
  if (!text.empty()) {
    const char last = text.back();
    scale = last == 'k' ? 1u << 10 : last == 'M' ? 1u << 20 : last == 'G' ? 1u << 30 : 1;
    if (scale != 1) text.remove_suffix(1);
  }
  std::uint64_t n = 0;
  const auto result = std::from_chars(text.data(), text.data() + text.size(), n);
  if (text.empty() || result.ec != std::errc() || result.ptr != text.data() + text.size()) {
    return false;
  }
  if (n == 0 || n > kMaxModelLimit / scale) return false;
  value = n * scale;
  return true;
}

}  // namespace

bool parseModelLimits(std::string_view text, ocean_scene::GltfLimits& limits, std::string& error) {
  const std::string usage =
      " (KEY=N[,KEY=N]...: triangles, instances, nodes, bytes, json-values or pixels, "
      "N in "
      "[1, 2^40], a k/M/G suffix allowed)";
  if (text.empty()) {
    error = "--model-limits is empty" + usage;
    return false;
  }
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find(',', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view item = text.substr(start, end - start);
    const std::size_t equals = item.find('=');
    const std::string_view key = item.substr(0, equals);
    std::uint64_t* field = key == "triangles"     ? &limits.triangles
                           : key == "instances"   ? &limits.instances
                           : key == "nodes"       ? &limits.nodes
                           : key == "bytes"       ? &limits.bytes
                           : key == "json-values" ? &limits.jsonValues
                           : key == "pixels"      ? &limits.pixels
                                                  : nullptr;
    if (field == nullptr || equals == std::string_view::npos) {
      error = "--model-limits: '" + std::string(item) + "' is not KEY=N" + usage;
      return false;
    }
    if (!parseCount(item.substr(equals + 1), *field)) {
      error = "--model-limits " + std::string(key) + " must be a whole number in [1, 2^40], got '" +
              std::string(item.substr(equals + 1)) + "'";
      return false;
    }
    start = end + 1;
  }
  return true;
}

}  // namespace ocean
