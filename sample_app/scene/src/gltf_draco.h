#pragma once
// KHR_draco_mesh_compression primitives decoded with Debian's libdraco (private to the loader).

#include <cstdint>
#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace ocean_scene::gltf {

// Whether the primitive carries KHR_draco_mesh_compression.
bool isDracoPrimitive(const tinygltf::Primitive& primitive);

// Decodes the primitive's compressed bufferView: positions (the extension's POSITION
// attribute), normals (its NORMAL attribute, left empty when it maps none) and the triangle
// list. The result is held to the primitive's own accessors: as many points as the POSITION
// accessor's count, finite, inside its min/max (to Draco's quantisation step); every index in
// range. One-line `error` on a malformed extension, a bufferView outside its buffer, or data
// the decoder refuses.
bool decodeDracoPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                          std::vector<glm::vec3>& positions, std::vector<glm::vec3>& normals,
                          std::vector<std::uint32_t>& indices, std::string& error);

}  // namespace ocean_scene::gltf
