#pragma once
// The regression corpus: every hostile or odd file found so far, generated here
// (no committed binaries) so that the loader's tests, its message-length test and its fuzz
// target all start from the same files. Each case is a folder: the model and the files it
// refers to, what a refusal must say, or that it loads.

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace gltf_hostile_corpus {

namespace fs = std::filesystem;
using Bytes = std::vector<unsigned char>;

struct Case {
  std::string name;                                  // the case's folder
  std::string model;                                 // the model's file name in it
  std::vector<std::pair<std::string, Bytes>> files;  // the model and the files beside it
  // A refusal's message contains this; "" when the case loads.
  std::string mentions;
  // A load's notes contain this ("" when nothing is expected of them).
  std::string notes;
};

// The three files that multiply their work without bound, small on disk:
// 100,000 primitives reusing one 1024-triangle sphere; 250 nodes x 4000 EXT_mesh_gpu_instancing
// copies of a 10,000-triangle sphere (10^10 triangles); a million nodes drawing a sphere.
Bytes manyPrimitives(int primitives);
Bytes instancedTriangles(int nodes, int copies);
Bytes manyNodes(int nodes);

// Every case; `scratch` is a folder the PNGs are written to on their way (OpenImageIO writes
// files, not memory).
std::vector<Case> corpus(const fs::path& scratch);

// Writes the case under `root` (root/name/...) and returns the model's path.
fs::path write(const fs::path& root, const Case& c);

}  // namespace gltf_hostile_corpus
