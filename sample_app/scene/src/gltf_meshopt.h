#pragma once
// EXT_meshopt_compression buffer views decoded with Debian's libmeshoptimizer (private to the
// loader). The preflight gives each data-less fallback buffer a 4-byte placeholder so tinygltf
// parses the file; here every compressed bufferView is decoded into a buffer of its own and
// pointed at it, so the accessor reads that follow see plain glTF data.

#include <set>
#include <string>

#include <tiny_gltf.h>

namespace ocean_scene::gltf {

// Decoded bytes above this are refused (a sample caster is a few MB; the file itself is at most
// 1 GiB, and meshopt rarely compresses more than 8:1).
inline constexpr std::size_t kMaxMeshoptDecodedBytes = std::size_t(1) << 30;
// meshopt's densest encodings: 2 header bits per 16 vertex bytes (64:1), a byte or so per
// triangle (12:1). A view claiming more than this many decoded bytes per compressed byte is
// refused before its output is allocated, so a tiny hostile file cannot ask for a GiB.
inline constexpr std::size_t kMaxMeshoptRatio = 128;

// `fallbacks`: the buffers the preflight found to be meshopt fallbacks (no data of their own).
// Any bufferView still reading one after decoding is an error. One-line `error` naming the
// bufferView on a malformed extension (mode, filter, stride, count), a source range outside
// its buffer, or data the decoder refuses.
bool decodeMeshoptViews(tinygltf::Model& model, const std::set<std::size_t>& fallbacks,
                        std::string& error);

}  // namespace ocean_scene::gltf
