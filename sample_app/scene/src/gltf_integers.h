#pragma once
// Integers tinygltf would narrow (private to the loader). tinygltf keeps most of a glTF's
// integers in an `int` (indices, the sparse accessor's count and byte offsets, modes) and every
// integer inside an extension in an int Value, converting with a plain cast: 2^40 becomes 0,
// 2^63 becomes 0 and 2^31 becomes -2147483648, without a word. Each integer it would narrow is
// checked here from the raw JSON, before tinygltf parses it.

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace ocean_scene::gltf {

// False, naming the first integer beyond int's range by its JSON path and exact value
// ("accessors[0].sparse.values.byteOffset is 1099511627776, ..."). The fields tinygltf keeps
// in 64 bits (accessor byteOffset, count; bufferView byteOffset, byteLength, byteStride;
// buffer byteLength) are left to the bounds checks; "extras" and extensions the loader does
// not read are neither read nor checked.
bool integersFit(const nlohmann::json& root, std::string& error);

}  // namespace ocean_scene::gltf
