#pragma once
// Writes a Model as a binary glTF (.glb) through tinygltf's writer.

#include <string>

#include "scene/model.h"

namespace ocean_scene {

// One glTF mesh (one primitive) per Mesh, one node per Instance (matrix omitted when identity),
// materials with KHR_materials_ior / _transmission / _volume where they differ from the
// defaults. Indices are stored as u16 when the mesh allows it. Returns false with a one-line
// message on invalid input or I/O failure; never throws.
bool writeGlb(const Model& model, const std::string& path, std::string& error);

}  // namespace ocean_scene
