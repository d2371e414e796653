#pragma once
// GLSL sources embedded at build time (see cmake/EmbedShaders.cmake), looked up by their path
// relative to shaders/, with #include "path" resolved against the same set.
#include <span>
#include <string>
#include <string_view>

namespace glkit {

struct ShaderFile {
  std::string_view path;    // relative to shaders/, e.g. "gbuffer/reconstruct.glsl"
  std::string_view source;  // the file's text
};

class ShaderLibrary {
 public:
  // overrideDirectory: when non-empty, files are read from disk there first (development only).
  ShaderLibrary(std::span<const ShaderFile> files, std::string_view overrideDirectory);

  // The text of one file, or false when the library does not hold it.
  bool load(std::string_view path, std::string& text) const;

  // Expands #include "path" directives (each file at most once, like #pragma once) and inserts
  // `defines` right after the #version line. Returns false with a message naming the file and
  // line on a missing include.
  bool preprocess(std::string_view path, std::string_view defines, std::string& out,
                  std::string& error) const;

 private:
  std::span<const ShaderFile> files_;
  std::string overrideDirectory_;
};

}  // namespace glkit
