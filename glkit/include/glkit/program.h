#pragma once
// Compiling and linking GL programs from a ShaderLibrary, with #defines chosen at creation.
#include <epoxy/gl.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include <glkit/shader_library.h>

namespace glkit {

struct ShaderStage {
  GLenum type;            // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER, ...
  std::string_view path;  // relative to shaders/
};

// Builds a program; on failure returns false, sets `error` to the compiler or linker log and
// leaves `program` 0 with nothing allocated. `label` names the program for debuggers.
bool buildProgram(const ShaderLibrary& library, std::initializer_list<ShaderStage> stages,
                  std::string_view defines, std::string_view label, GLuint& program,
                  std::string& error);

// A program deleted when it goes out of scope; movable, not copyable.
class Program {
 public:
  Program() = default;
  explicit Program(GLuint id) : id_(id) {}
  Program(Program&& other) noexcept : id_(other.id_) { other.id_ = 0; }
  Program& operator=(Program&& other) noexcept;
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;
  ~Program();
  GLuint id() const { return id_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(id_, name); }

 private:
  GLuint id_ = 0;
};

// Labels a GL object for debuggers (KHR_debug); a no-op for empty labels.
void label(GLenum identifier, GLuint name, std::string_view text);

}  // namespace glkit
