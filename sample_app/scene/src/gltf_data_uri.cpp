#include "gltf_data_uri.h"

#include <cstdint>
#include <cstdio>

#include "gltf_text.h"

namespace ocean_scene::gltf {

namespace {

int base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

// The base64 after the comma, or an empty view when there is none.
std::string_view payload(std::string_view uri) {
  const std::size_t comma = uri.find(',');
  return comma == std::string_view::npos ? std::string_view() : uri.substr(comma + 1);
}

}  // namespace

bool isDataUri(std::string_view uri) {
  return uri.substr(0, 5) == "data:";
}

bool checkDataUri(std::string_view uri, DataUri& out, std::string& reason) {
  out = DataUri{};
  const std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) {
    reason = "has no ',' before its data";
    return false;
  }
  const std::string_view header = uri.substr(5, comma - 5);
  const std::string_view suffix = ";base64";
  if (header.size() < suffix.size() || header.substr(header.size() - suffix.size()) != suffix) {
    reason = "is not base64 (no ';base64' before the ','); only base64 data is read";
    return false;
  }
  out.mediaType = std::string(header.substr(0, header.size() - suffix.size()));
  const std::string_view data = uri.substr(comma + 1);
  std::size_t padding = 0;
  for (std::size_t i = 0; i < data.size(); ++i) {
    const char c = data[i];
    const bool inPadding = c == '=' && i + 2 >= data.size() && data.size() % 4 == 0;
    if (padding > 0 && c != '=') {
      reason = "has data after its base64's '=' padding, at character " + std::to_string(i);
      return false;
    }
    if (inPadding) {
      ++padding;
      continue;
    }
    if (base64Value(c) < 0) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02X", unsigned(static_cast<unsigned char>(c)));
      reason = "has '" + excerpt(std::string_view(&data[i], 1)) + "' (" + code + ") at character " +
               std::to_string(i) + " of its base64, not a base64 character";
      return false;
    }
  }
  const std::size_t digits = data.size() - padding;
  if (digits % 4 == 1) {
    reason = "ends its base64 with a lone character (" + std::to_string(digits) + " digits)";
    return false;
  }
  out.decodedSize = digits / 4 * 3 + (digits % 4 == 0 ? 0 : digits % 4 - 1);
  return true;
}

std::vector<unsigned char> decodeDataUri(std::string_view uri) {
  const std::string_view data = payload(uri);
  std::vector<unsigned char> out;
  out.reserve(data.size() / 4 * 3 + 3);
  std::uint32_t bits = 0;
  int held = 0;
  for (char c : data) {
    const int v = base64Value(c);
    if (v < 0) break;  // the padding
    bits = (bits << 6) | std::uint32_t(v);
    held += 6;
    if (held >= 8) {
      held -= 8;
      out.push_back(static_cast<unsigned char>(bits >> held));
    }
  }
  return out;
}

}  // namespace ocean_scene::gltf
