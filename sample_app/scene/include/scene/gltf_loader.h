#pragma once
// glTF 2.0 loading through tinygltf, with the checks tinygltf leaves to the caller: every
// accessor used is bounds-checked against its buffer view and buffer, element types are the
// ones expected, index values are in range, positions are finite.

#include <string>

#include "scene/model.h"

namespace ocean_scene {

// Loads a .glb (or a .gltf; the format is told by the file's first bytes, not its name) into
// `out`: one Mesh per primitive (mesh space), one Instance per node that has a mesh, with the
// node hierarchy's transforms flattened into Instance::transform. Missing normals are
// generated. Only triangle primitives are accepted. Materials include KHR_materials_ior,
// KHR_materials_transmission and KHR_materials_volume; textures are ignored.
//
// Returns false with a one-line `error` ("<path>: <problem>") and leaves `out` empty on any
// problem; never throws and never prints. Non-fatal notes (tinygltf warnings, regenerated
// normals) go to `warnings` when it is given.
bool loadGlb(const std::string& path, Model& out, std::string& error,
             std::string* warnings = nullptr);

}  // namespace ocean_scene
