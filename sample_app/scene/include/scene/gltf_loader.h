#pragma once
// glTF 2.0 loading through tinygltf, with the checks tinygltf leaves to the caller: every
// accessor used is bounds-checked against its buffer view and buffer, element types are the
// ones expected, index values are in range, positions are finite and inside the accessor's
// min/max. The file is treated as hostile: JSON nesting is bounded before tinygltf's recursive
// parse, only regular files are opened (never blocking on a FIFO), buffer URIs are read only
// from inside the model's own folder, no image file but a base colour's is opened, and node
// transforms are checked composed, as the float matrices the renderer uses. What the file's
// counts expand to is held to a budget (scene/gltf_limits.h) before anything is expanded.

#include <string>

#include "scene/gltf_limits.h"
#include "scene/model.h"

namespace ocean_scene {

// Loads a .glb (or a .gltf; the format is told by the file's first bytes, not its name) into
// `out`: one Mesh per primitive (mesh space), one Instance per node that has a mesh, with the
// node hierarchy's transforms flattened into Instance::transform. Missing normals are
// generated. Triangle lists, strips and fans are accepted (strips and fans become lists);
// sparse accessors, KHR_mesh_quantization and EXT_mesh_gpu_instancing (one Instance per copy)
// are read; KHR_draco_mesh_compression (libdraco) and EXT_meshopt_compression
// (libmeshoptimizer) are decoded, the decoded data held to the same checks. Other unsupported
// extensionsRequired are refused by name. Materials include KHR_materials_ior (0 = the spec's
// infinite IOR), KHR_materials_transmission, KHR_materials_volume and
// KHR_materials_dispersion; a base-colour texture's mean colour scales the base colour
// wherever its PNG or JPEG is (a bufferView, a data: URI, a file inside the model's folder:
// the only image files ever opened), other textures are not used (a note names each textured
// material). A node whose composed transform is not invertible (scale 0: hidden) is left out
// with a note.
//
// Returns false with a one-line `error` ("<path>: <problem>") and leaves `out` empty on any
// problem; never throws and never prints (what a library it calls prints on stderr, libpng's
// errors for one, is caught and named in its messages). Non-fatal notes (tinygltf warnings,
// regenerated normals, hidden nodes left out, images not read) go to `warnings` when it is
// given, as one line of "; "-separated notes. Every value from the file quoted in either is at
// most gltf kMaxQuotedChars (200) characters, cut with "... (N bytes)".
bool loadGlb(const std::string& path, Model& out, std::string& error,
             std::string* warnings = nullptr, const GltfLimits& limits = {});

}  // namespace ocean_scene
