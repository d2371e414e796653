#include "gltf_glb.h"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>

namespace ocean_scene::gltf {

namespace {

constexpr std::uint32_t kJson = 0x4E4F534Au;  // "JSON", little-endian
constexpr std::uint32_t kBin = 0x004E4942u;   // "BIN\0"

std::uint32_t u32(const std::vector<unsigned char>& bytes, std::size_t at) {
  std::uint32_t v;
  std::memcpy(&v, bytes.data() + at, 4);
  return v;  // GLB is little-endian, as are the machines this sample targets
}

// "0x4E4F534A ('JSON')": a chunk type as the file has it, printable characters only.
std::string typeText(std::uint32_t type) {
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%08X", unsigned(type));
  std::string letters;
  for (int i = 0; i < 4; ++i) {
    const auto c = static_cast<unsigned char>(type >> (8 * i));
    letters += std::isprint(c) ? char(c) : '.';
  }
  return std::string(hex) + " ('" + letters + "')";
}

// The chunks after the BIN chunk, from `at` to the GLB's `length`: the spec lets a reader skip
// chunks of other types, but each must lie inside the GLB, and there is at most one BIN chunk
// (tinygltf read the first and said nothing of a second, or of a chunk running past the end).
bool laterChunksValid(const std::vector<unsigned char>& bytes, std::uint64_t at,
                      std::uint64_t length, std::string& error) {
  while (at < length) {
    const std::string where = std::to_string(at);
    if (length - at < 8) {
      error = "GLB chunk header at byte " + where +
              " cut short: the GLB's length (byte 8) ends it " + std::to_string(length - at) +
              " bytes later, a chunk header needs 8";
      return false;
    }
    const std::uint32_t type = u32(bytes, at + 4);
    if (type == kBin) {
      error = "GLB has a second BIN chunk at byte " + where +
              "; a GLB holds at most one (the one after the JSON chunk): merge their data into "
              "one buffer";
      return false;
    }
    const std::uint64_t chunkLength = u32(bytes, at);
    if (at + 8 + chunkLength > length) {
      error = "GLB chunk " + typeText(type) + " at byte " + where + " has length " +
              std::to_string(chunkLength) + ": it would end at byte " +
              std::to_string(at + 8 + chunkLength) + ", past the GLB's length " +
              std::to_string(length) + " (byte 8)";
      return false;
    }
    at += 8 + chunkLength;
  }
  return true;
}

}  // namespace

bool isGlb(const std::vector<unsigned char>& bytes) {
  return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

bool readGlbLayout(const std::vector<unsigned char>& bytes, GlbLayout& out, std::string& error) {
  const std::size_t size = bytes.size();
  const std::string fileSize = std::to_string(size);
  if (size < 12) {
    error = "GLB header cut short: the file has " + fileSize +
            " bytes, the header (magic, version at byte 4, length at byte 8) needs 12";
    return false;
  }
  if (const std::uint32_t version = u32(bytes, 4); version != 2) {
    error = "GLB version (byte 4) is " + std::to_string(version) + "; only 2 is read";
    return false;
  }
  const std::uint64_t length = u32(bytes, 8);
  if (length > size) {
    error = "GLB length (byte 8) is " + std::to_string(length) + " bytes but the file has " +
            fileSize + ": it is cut short";
    return false;
  }
  if (length < 20) {
    error = "GLB length (byte 8) is " + std::to_string(length) +
            "; the 12-byte header and the JSON chunk's 8-byte header need 20";
    return false;
  }
  if (const std::uint32_t type = u32(bytes, 16); type != kJson) {
    error = "GLB first chunk's type (byte 16) is " + typeText(type) + ", not JSON";
    return false;
  }
  const std::uint64_t jsonLength = u32(bytes, 12);
  if (jsonLength == 0) {
    error = "GLB JSON chunk's length (byte 12) is 0";
    return false;
  }
  const std::uint64_t jsonEnd = 20 + jsonLength;
  if (jsonEnd > length) {
    error = "GLB JSON chunk's length (byte 12) is " + std::to_string(jsonLength) +
            " bytes: it would end at byte " + std::to_string(jsonEnd) + ", past the GLB's length " +
            std::to_string(length) + " (byte 8)";
    return false;
  }
  out = GlbLayout{};
  out.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20,
                              static_cast<std::size_t>(jsonLength));
  out.jsonEnd = static_cast<std::size_t>(jsonEnd);
  out.length = static_cast<std::size_t>(length);
  if (jsonEnd == length) return true;  // no BIN chunk
  const std::string at = std::to_string(jsonEnd);
  if (length - jsonEnd < 8) {
    error = "GLB chunk header at byte " + at + " cut short: the GLB's length (byte 8) ends it " +
            std::to_string(length - jsonEnd) + " bytes later, a chunk header needs 8";
    return false;
  }
  if (const std::uint32_t type = u32(bytes, jsonEnd + 4); type != kBin) {
    error = "GLB second chunk's type (byte " + std::to_string(jsonEnd + 4) + ") is " +
            typeText(type) + ", not BIN";
    return false;
  }
  const std::uint64_t binLength = u32(bytes, jsonEnd);
  if (binLength == 0 || binLength % 4 != 0) {
    error = "GLB BIN chunk's length (byte " + at + ") is " + std::to_string(binLength) +
            "; it must be a positive multiple of 4";
    return false;
  }
  if (jsonEnd + 8 + binLength > length) {
    error = "GLB BIN chunk's length (byte " + at + ") is " + std::to_string(binLength) +
            " bytes: it would end at byte " + std::to_string(jsonEnd + 8 + binLength) +
            ", past the GLB's length " + std::to_string(length) + " (byte 8)";
    return false;
  }
  out.binHeader = static_cast<std::size_t>(jsonEnd);
  out.binLength = static_cast<std::size_t>(binLength);
  return laterChunksValid(bytes, jsonEnd + 8 + binLength, length, error);
}

}  // namespace ocean_scene::gltf
