#pragma once
// The GLB container (glTF 2.0 spec, "Binary glTF Layout"; private to the loader), checked
// field by field before tinygltf sees it: tinygltf reports most damage as "Invalid glTF
// binary." and, for a BIN chunk whose length runs into the last 8 bytes, reads past the end.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace ocean_scene::gltf {

struct GlbLayout {
  std::string_view json;      // the JSON chunk's bytes
  std::size_t jsonEnd = 0;    // the byte after the JSON chunk
  std::size_t binHeader = 0;  // where the BIN chunk's 8-byte header is (0: no BIN chunk)
  std::size_t binLength = 0;  // its data's length
  std::size_t length = 0;     // the header's length field: the GLB's end
};

// Whether `bytes` start with the GLB magic "glTF".
bool isGlb(const std::vector<unsigned char>& bytes);

// The chunks of a GLB. False with one line naming the field, its byte offset and the value
// found: a header cut short, a version other than 2, a length beyond the file, a first chunk
// that is not JSON or is empty, a chunk that runs past the GLB's length, a second chunk that is
// not BIN or whose length is not a positive multiple of 4, a second BIN chunk, or a later chunk
// that runs past the GLB's length.
bool readGlbLayout(const std::vector<unsigned char>& bytes, GlbLayout& out, std::string& error);

}  // namespace ocean_scene::gltf
