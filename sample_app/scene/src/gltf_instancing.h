#pragma once
// EXT_mesh_gpu_instancing (private to the loader): one node drawn many times, each copy with
// its own translation, rotation and scale from accessors.

#include <string>
#include <vector>

#include <tiny_gltf.h>
#include <glm/glm.hpp>

namespace ocean_scene::gltf {

// The sample draws and casts each copy separately, so a file asking for more is refused.
inline constexpr std::size_t kMaxGpuInstances = 4096;

// Fills `out` with each copy's transform in the node's space (T * R * S); leaves it empty when
// the node does not use the extension. False with a one-line reason on a malformed extension.
bool readGpuInstances(const tinygltf::Model& model, const tinygltf::Node& node,
                      std::vector<glm::dmat4>& out, std::string& error);

}  // namespace ocean_scene::gltf
