#pragma once
// Rules of the glTF 2.0 specification tinygltf does not hold a file to, or holds it to with a
// message that names neither the field nor the rule (private to the loader). Each refusal
// names the JSON path, the value, what the spec accepts and the fix.

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace ocean_scene::gltf {

// False with one line for the first rule broken:
//  - asset.version must be a string "2.x" (a glTF 1.0 file is read wrongly, not refused);
//  - a bufferView's byteStride, when present, must be a multiple of 4 in [4, 252];
//  - a material's baseColorFactor must be 4 numbers (tinygltf keeps [1] and the loader then
//    ignored it);
//  - a primitive's index accessor must have a bufferView (tinygltf: "accessor[0] invalid
//    bufferView"), Draco primitives aside (their triangles are in the compressed data).
bool followsSpecRules(const nlohmann::json& root, std::string& error);

}  // namespace ocean_scene::gltf
