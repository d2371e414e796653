#pragma once
// Messages built from a model's bytes (private to the loader): a file can put anything in a
// name or a URI, and a terminal must only ever receive one short line of valid UTF-8.

#include <cstddef>
#include <string>
#include <string_view>

namespace ocean_scene::gltf {

// The most characters of one value from the file (a name, a URI, a library's line) that a
// message quotes; a longer value is cut there and says how long it was.
inline constexpr std::size_t kMaxQuotedChars = 200;
// The most characters of a whole message after the file's name: a last guard, since every
// value in it is already quoted within kMaxQuotedChars.
inline constexpr std::size_t kMaxMessageChars = 1000;
// The most characters of a load's notes (a few named materials, nodes, meshes, then counts).
inline constexpr std::size_t kMaxNotesChars = 4000;

// Line breaks become "; "; control characters and bytes that are not valid UTF-8 become \xNN;
// trailing separators are dropped.
std::string safeOneLine(std::string_view text);

// `value` as safeOneLine makes it (but a line break is \x0A: it is inside one value), cut
// after `limit` characters at a character boundary with "… (N bytes)" added, N the value's
// own length (or `ofBytes`, when the value is itself a part of something longer).
std::string excerpt(std::string_view value, std::size_t limit = kMaxQuotedChars,
                    std::size_t ofBytes = 0);

}  // namespace ocean_scene::gltf
