#pragma once
// Compiling and linking GL programs from a ShaderLibrary, with #defines chosen at creation.
#include <epoxy/gl.h>

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include <glkit/handle.h>
#include <glkit/shader_library.h>

namespace glkit {

struct ShaderStage {
  GLenum type;            // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
  std::string_view path;  // relative to shaders/
};

// A program deleted when it goes out of scope; movable, not copyable.
class Program : public Handle<GLuint, deleteProgram> {
 public:
  using Handle::Handle;
  GLint uniform(const char* name) const { return glGetUniformLocation(id(), name); }
};

// Rewrites one stage's preprocessed source before it is compiled (instrumentation).
using SourceFilter = std::function<void(GLenum stage, std::string& source)>;

// Builds a program; on failure returns an empty Program (nothing allocated) and sets `error` to
// the compiler or linker log. `label` names the program for debuggers; `filter`, when given,
// rewrites each stage's source first.
Program buildProgram(const ShaderLibrary& library, std::initializer_list<ShaderStage> stages,
                     std::string_view defines, std::string_view label, std::string& error,
                     const SourceFilter& filter = {});

// Labels a GL object for debuggers (KHR_debug); a no-op for empty labels.
void label(GLenum identifier, GLuint name, std::string_view text);

}  // namespace glkit
