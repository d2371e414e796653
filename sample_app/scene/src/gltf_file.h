#pragma once
// File access for the loader (private to it). Paths come from the user and from the model, so
// nothing is opened that could block (a FIFO), stream forever (a device) or lie outside the
// model's own folder.

#include <cstdint>
#include <string>
#include <vector>

namespace ocean_scene::gltf {

// Reads a whole regular file. Anything else (directory, FIFO, device, socket) is refused from
// stat() before it is opened, and again from fstat() after an O_NONBLOCK open, so a FIFO
// swapped in between cannot block either.
bool readRegularFile(const std::string& path, std::uint64_t maxBytes,
                     std::vector<unsigned char>& bytes, std::string& error);

// tinygltf's percent-decoding of a URI ('+' is a space), so a check sees what it will open.
std::string decodeUri(const std::string& uri);

// The absolute, symlink-free path of `folder`, or "" when it does not exist.
std::string realFolder(const std::string& folder);

// Resolves a (decoded) relative URI inside `folder` (a realFolder result) to the regular file
// it names, its "." and ".." segments resolved lexically first ("sub/../a.bin" is "a.bin").
// Refused, with a reason that never quotes another file's size or bytes: a scheme (file:,
// http:, ...), an absolute path, a ".." above the folder, the folder itself ("." or ""), a
// symbolic link that leads out of the folder, a missing file, or anything that is not a
// regular file.
bool resolveInFolder(const std::string& folder, const std::string& rawUri,
                     const std::string& decodedUri, std::string& resolved, std::string& error);

}  // namespace ocean_scene::gltf
