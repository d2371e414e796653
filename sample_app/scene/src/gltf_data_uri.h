#pragma once
// data: URIs (RFC 2397) in buffers and images (private to the loader), checked before
// tinygltf decodes them: tinygltf's decoder stops at the first byte that is not base64 and
// its error quotes the whole URI (tens of MB on one line) without saying what was wrong.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ocean_scene::gltf {

bool isDataUri(std::string_view uri);

struct DataUri {
  std::string mediaType;        // as written before ";base64" ("" when there is none)
  std::size_t decodedSize = 0;  // bytes the base64 decodes to
};

// Parses "data:<media type>;base64,<base64>" and checks every character of the base64 (the
// alphabet of RFC 4648, '=' padding only at the end). False with the reason, a predicate of
// the URI ("has no ','", "is not base64", "has '!' (0x21) at character 12 of its base64").
bool checkDataUri(std::string_view uri, DataUri& out, std::string& reason);

// The bytes of a data: URI that checkDataUri accepted.
std::vector<unsigned char> decodeDataUri(std::string_view uri);

}  // namespace ocean_scene::gltf
