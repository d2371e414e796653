#pragma once
// --model-limits KEY=N[,KEY=N]...: raises (or lowers) the work budget the glTF loader holds a
// --model file to (scene/gltf_limits.h), for a file that is large on purpose.

#include <string>
#include <string_view>

#include <scene/gltf_limits.h>

namespace ocean {

// Each limit may be set to at most this (2^40): far beyond what the sample can draw, and
// small enough that no sum of them overflows.
inline constexpr std::uint64_t kMaxModelLimit = std::uint64_t(1) << 40;

// KEY is triangles, instances, nodes, bytes, json-values or pixels; N a whole number in [1, 2^40],
// optionally with a binary suffix k, M or G (bytes=2G). Keys not given keep their value in
// `limits`. False with a one-line reason naming the key.
bool parseModelLimits(std::string_view text, ocean_scene::GltfLimits& limits, std::string& error);

}  // namespace ocean
