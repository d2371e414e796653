#pragma once
// The one rule for every index a glTF file holds (private to the loader): an integer >= 0,
// written as one. tinygltf reads -1 (and -0, and any negative) as "none" or as 0 and skips an
// index written 1.0, while the work budget counts only what an index really points at, so a
// file with "scene": -0 or "mesh": -0 was drawn from scene 0 / mesh 0 with nothing of it
// counted: a 10^10-triangle file the budget refuses in 2 s ran for minutes.

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace ocean_scene::gltf {

// "" when `value` is a JSON integer >= 0 written as one (7, not 7.0, 7e0 or -0); else how the
// file wrote it, for a message: "-5", "-0", "24.0", "a string", "an array".
std::string notANaturalNumber(const nlohmann::json& value);

// The fix for a count or offset field that is not one: "it must be a non-negative integer
// (24, not 24.0 or 2.4e1)".
std::string naturalNumberRule(const nlohmann::json& value);

// False, naming the first index that breaks the rule by its JSON path, the value as written,
// what it indexes and the fix ("nodes[3].mesh is -5; an index must be an integer >= 0 (the
// position of an entry of "meshes"), written without sign, fraction or exponent: leave
// nodes[3].mesh out to refer to none"). Every index field of glTF 2.0 and of the extensions
// the loader reads is checked: scene, scenes' nodes, children, mesh, camera, skin, material,
// attributes, targets, indices, accessor and image bufferViews, buffer, texture index,
// texCoord, source, sampler, skins' and animations' indices. Out-of-range indices are left to
// the checks that follow.
bool indicesValid(const nlohmann::json& root, std::string& error);

}  // namespace ocean_scene::gltf
