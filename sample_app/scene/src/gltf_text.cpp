#include "gltf_text.h"

#include <cstdio>

namespace ocean_scene::gltf {

namespace {

// Length of the valid UTF-8 sequence starting at text[i] (1..4), or 0 if it is not one.
// Overlong forms, surrogates and code points above U+10FFFF are invalid (RFC 3629).
std::size_t utf8Length(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char lead = byte(i);
  if (lead < 0x80) return 1;
  std::size_t length = 0;
  unsigned int lowest = 0;
  if (lead >= 0xC2 && lead <= 0xDF) {
    length = 2;
    lowest = 0x80;
  } else if (lead >= 0xE0 && lead <= 0xEF) {
    length = 3;
    lowest = 0x800;
  } else if (lead >= 0xF0 && lead <= 0xF4) {
    length = 4;
    lowest = 0x10000;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  unsigned int code = lead & (0x7F >> length);
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  if (code < lowest || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return 0;
  return length;
}

// One character of `text` at i as it may be printed, and how many bytes it took.
std::string printable(std::string_view text, std::size_t i, std::size_t& taken) {
  const std::size_t length = utf8Length(text, i);
  const auto lead = static_cast<unsigned char>(text[i]);
  if (length == 0 || (length == 1 && (lead < 0x20 || lead == 0x7F))) {
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02X", lead);
    taken = 1;
    return escaped;
  }
  taken = length;
  return std::string(text.substr(i, length));
}

}  // namespace

std::string excerpt(std::string_view value, std::size_t limit, std::size_t ofBytes) {
  std::string out;
  std::size_t characters = 0;
  for (std::size_t i = 0; i < value.size();) {
    if (characters == limit) {
      return out + "\u2026 (" + std::to_string(ofBytes > value.size() ? ofBytes : value.size()) +
             " bytes)";
    }
    std::size_t taken = 0;
    out += printable(value, i, taken);
    i += taken;
    ++characters;
  }
  return out;
}

std::string safeOneLine(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (c == '\n' || c == '\r') {
      if (!out.empty() && out.back() != ' ') out += "; ";
      ++i;
      continue;
    }
    std::size_t taken = 0;
    out += printable(text, i, taken);
    i += taken;
  }
  while (!out.empty() && (out.back() == ' ' || out.back() == ';')) out.pop_back();
  return out;
}

}  // namespace ocean_scene::gltf
