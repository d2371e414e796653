#include <glkit/shader_library.h>

#include <fstream>
#include <set>
#include <sstream>

namespace glkit {
namespace {

// Returns the path inside `#include "path"`, or an empty view when the line is no include.
std::string_view includeTarget(std::string_view line) {
  const size_t first = line.find_first_not_of(" \t");
  if (first == std::string_view::npos || line.substr(first, 8) != "#include") return {};
  const size_t open = line.find('"', first + 8);
  const size_t close = open == std::string_view::npos ? open : line.find('"', open + 1);
  if (close == std::string_view::npos) return {};
  return line.substr(open + 1, close - open - 1);
}

bool expand(const ShaderLibrary& library, std::string_view path, std::set<std::string>& seen,
            std::string& out, std::string& error) {
  if (!seen.insert(std::string(path)).second) return true;
  std::string text;
  if (!library.load(path, text)) {
    error = "shader file not found: " + std::string(path);
    return false;
  }
  std::istringstream lines(text);
  std::string line;
  int lineNumber = 0;
  while (std::getline(lines, line)) {
    ++lineNumber;
    const std::string_view target = includeTarget(line);
    if (target.empty()) {
      out += line;
      out += '\n';
      continue;
    }
    if (!expand(library, target, seen, out, error)) {
      error = std::string(path) + ":" + std::to_string(lineNumber) + ": " + error;
      return false;
    }
  }
  return true;
}

}  // namespace

ShaderLibrary::ShaderLibrary(std::span<const ShaderFile> files, std::string_view overrideDirectory)
    : files_(files), overrideDirectory_(overrideDirectory) {}

bool ShaderLibrary::load(std::string_view path, std::string& text) const {
  if (!overrideDirectory_.empty()) {
    std::ifstream file(overrideDirectory_ + "/" + std::string(path), std::ios::binary);
    if (file) {
      std::ostringstream buffer;
      buffer << file.rdbuf();
      text = buffer.str();
      return true;
    }
  }
  for (const ShaderFile& file : files_) {
    if (file.path == path) {
      text = file.source;
      return true;
    }
  }
  return false;
}

bool ShaderLibrary::preprocess(std::string_view path, std::string_view defines, std::string& out,
                               std::string& error) const {
  std::set<std::string> seen;
  std::string body;
  if (!expand(*this, path, seen, body, error)) return false;
  // GLSL requires #version first; everything we inject goes after it.
  const size_t version = body.find("#version");
  const size_t lineEnd = version == std::string::npos ? 0 : body.find('\n', version) + 1;
  out = body.substr(0, lineEnd);
  out += "#define POSTFX_GLSL 1\n";
  out += defines;
  if (!defines.empty() && defines.back() != '\n') out += '\n';
  out += "#line 2\n";
  out += body.substr(lineEnd);
  return true;
}

}  // namespace glkit
