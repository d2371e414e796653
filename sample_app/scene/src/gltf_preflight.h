#pragma once
// Checks on a glTF file's JSON made before tinygltf sees it (private to the loader).
// tinygltf parses recursively, reads URIs relative to the working directory as well as the
// model's folder, opens image files it is not asked to decode, reads a negative byteOffset as
// 0 and loads files whose extensionsRequired it does not implement. Each of those is settled
// here, from the raw JSON, with a message that names the field.

#include <map>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "scene/gltf_limits.h"

namespace ocean_scene::gltf {

// Deeper JSON is refused before any recursive parse. A glTF's own structure is at most about
// 8 deep; 64 leaves extras and extensions generous room.
inline constexpr int kMaxJsonDepth = 64;

// Where a base-colour image's bytes are, when they are not in a bufferView.
struct ImageSource {
  std::string dataUri;  // its data: URI, checked
  std::string file;     // or the regular file inside the model's folder it names
  std::string problem;  // or why its file is not read ("its file 'a.png' names no file ...")
};

struct Preflight {
  // Buffer files the file may read: tinygltf's lookup path (baseDir joined with the decoded
  // URI) -> the regular file inside the model's folder it resolved to.
  std::map<std::string, std::string> bufferFiles;
  // Decoded URIs of the image files no material's base colour uses: these are never opened.
  std::set<std::string> imageUris;
  // The images materials' base colours use (by image index) that have a data: URI or a file.
  std::map<std::size_t, ImageSource> baseColourImages;
  bool meshQuantization = false;  // KHR_mesh_quantization is used
  // EXT_meshopt_compression fallback buffers without a uri (no data of their own: every view
  // of them is compressed elsewhere). tinygltf cannot parse such a buffer, so each gets a
  // 4-byte placeholder in `rewrittenJson`; the meshopt decoder replaces the views.
  std::set<std::size_t> meshoptFallbacks;
  // The JSON tinygltf parses instead of the file's ("" = the file's as it is): the meshopt
  // placeholders, and Draco primitives without their "indices" (an accessor with no data,
  // which tinygltf refuses; the loader reads the triangles from the Draco data).
  std::string rewrittenJson;
};

// False, saying so, when the JSON text is UTF-16 or UTF-32 (a byte-order mark, or a NUL among
// its first bytes, where UTF-8 JSON has none): nlohmann reads it as "unexpected end of input"
// at the first NUL, and a byte-order mark as no JSON at all.
bool jsonIsUtf8(std::string_view text, std::string& error);

// `baseDir` is the directory tinygltf is given. Returns false with a one-line reason: a GLB
// container field (by byte offset), JSON nested too deep or malformed, an unsupported required
// extension, a negative size, an integer tinygltf would narrow, a work budget exceeded
// (`limits`), a buffer that is not where it says (a data: URI by reason, a file outside the
// folder or of another size, a missing BIN chunk) or a broken data: URI of an image.
bool preflight(const std::vector<unsigned char>& bytes, const std::string& baseDir,
               const GltfLimits& limits, Preflight& out, std::string& error);

// The file with its JSON replaced by `json`: the text itself for a .gltf, the GLB rebuilt
// (header, padded JSON chunk, the original chunks after it) for a .glb that preflight accepted.
std::vector<unsigned char> withJson(const std::vector<unsigned char>& bytes,
                                    const std::string& json);

// tinygltf's path join, so the names handed to its file callbacks can be matched.
std::string joinLikeTinygltf(const std::string& dir, const std::string& file);

}  // namespace ocean_scene::gltf
