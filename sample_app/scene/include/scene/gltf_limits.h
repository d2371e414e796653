#pragma once
// The work a glTF file may ask of the loader and of the sample that draws it. A small valid
// file can multiply its work without bound (one sphere reused by 100,000 primitives, a million
// instances of it, 10^10 instanced triangles, a texture shared by 2,000 materials, 50 M numbers
// in "extras"), so the loader adds up what the file's own counts
// will expand to and refuses it, naming each limit it exceeds, before expanding anything.

#include <cstdint>
#include <string>

namespace ocean_scene {

struct GltfLimits {
  // Triangles after instancing: each node's mesh's triangles (index count / 3, or count - 2 for
  // strips and fans) times its EXT_mesh_gpu_instancing copies, over the scene's node tree.
  // 4M: a few seconds a frame on a CPU rasteriser (llvmpipe).
  std::uint64_t triangles = std::uint64_t(1) << 22;
  // Instances after instancing: one per primitive per node copy (each is a draw call).
  std::uint64_t instances = std::uint64_t(1) << 14;
  // Entries of the file's "nodes" array.
  std::uint64_t nodes = std::uint64_t(1) << 16;
  // Bytes the model takes once expanded: its buffers' byteLength, its meshopt-decoded views,
  // every primitive's vertices (24 bytes: position, normal) and triangles (12 bytes), and
  // the instances. Primitives are counted whether or not a node draws them: all are read.
  std::uint64_t bytes = std::uint64_t(1) << 30;
  // Values in the JSON (every number, string, true/false/null, array and object, and every
  // object key), counted before any document is built: a parsed value costs the loader's
  // parse and tinygltf's about 175 bytes (measured), so 50 M zeros in "extras" (a 100 MB file)
  // took 9.7 GB. 1M: a file just under it loads in the budget tests' 500 MB (2M peaked at
  // 479 MB, 4M took 545 MB more than none); 50,000 nodes with a name, a mesh and a full
  // transform (~20 values each) still fit: a glTF's bulk is in its buffers, not its JSON.
  std::uint64_t jsonValues = std::uint64_t(1) << 20;
  // Pixels of the images decoded (width x height from each image's header, before decoding;
  // each image once, however many materials share it): the base colours' textures.
  // 32M: two 4096 x 4096 textures, about 10 s on one core.
  std::uint64_t pixels = std::uint64_t(1) << 25;

  // The option that raises these, named in the refusal ("--model-limits"); "" names none.
  std::string raiseOption;
};

}  // namespace ocean_scene
