#pragma once
// Bounds-checked reads of glTF accessors (private to the loader).

#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace ocean_scene::gltf {

// A vec3 accessor (POSITION, NORMAL): float, or with `quantizationAllowed`
// (KHR_mesh_quantization) 8/16-bit integers, normalised or not. Sparse accessors are applied;
// values outside the accessor's min/max are refused. `what` names it in error messages.
bool readVec3(const tinygltf::Model& model, int accessorIndex, const std::string& what,
              bool quantizationAllowed, std::vector<glm::vec3>& out, std::string& error);

// Any float vector accessor of glTF type `type` (TINYGLTF_TYPE_VEC4, ...), flattened; the same
// rules as readVec3.
bool readFloats(const tinygltf::Model& model, int accessorIndex, const std::string& what, int type,
                bool quantizationAllowed, std::vector<float>& out, std::string& error);

// A scalar u8/u16/u32 index accessor, widened to u32.
bool readIndices(const tinygltf::Model& model, int accessorIndex, std::vector<std::uint32_t>& out,
                 std::string& error);

}  // namespace ocean_scene::gltf
