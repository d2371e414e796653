#pragma once
// Messages built from a model's bytes (private to the loader): a file can put anything in a
// name or a URI, and a terminal must only ever receive one line of valid UTF-8.

#include <string>
#include <string_view>

namespace ocean_scene::gltf {

// Line breaks become "; "; control characters and bytes that are not valid UTF-8 become \xNN;
// trailing separators are dropped.
std::string safeOneLine(std::string_view text);

}  // namespace ocean_scene::gltf
