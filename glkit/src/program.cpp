#include <glkit/program.h>

#include <vector>

namespace glkit {
namespace {

std::string infoLog(GLuint object, bool isProgram) {
  GLint length = 0;
  if (isProgram) {
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  } else {
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  }
  std::string log(static_cast<size_t>(length > 0 ? length : 1), '\0');
  if (isProgram) {
    glGetProgramInfoLog(object, length, nullptr, log.data());
  } else {
    glGetShaderInfoLog(object, length, nullptr, log.data());
  }
  while (!log.empty() && (log.back() == '\0' || log.back() == '\n')) log.pop_back();
  return log;
}

}  // namespace

Program buildProgram(const ShaderLibrary& library, std::initializer_list<ShaderStage> stages,
                     std::string_view defines, std::string_view label, std::string& error,
                     const SourceFilter& filter) {
  std::vector<GLuint> shaders;
  auto cleanup = [&shaders] {
    for (GLuint shader : shaders) glDeleteShader(shader);
  };
  for (const ShaderStage& stage : stages) {
    std::string source;
    if (!library.preprocess(stage.path, defines, source, error)) {
      cleanup();
      return Program();
    }
    if (filter) filter(stage.type, source);
    const GLuint shader = glCreateShader(stage.type);
    shaders.push_back(shader);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (ok != GL_TRUE) {
      error = std::string(stage.path) + ": " + infoLog(shader, false);
      cleanup();
      return Program();
    }
  }
  const GLuint linked = glCreateProgram();
  for (GLuint shader : shaders) glAttachShader(linked, shader);
  glLinkProgram(linked);
  for (GLuint shader : shaders) glDetachShader(linked, shader);
  cleanup();
  GLint ok = GL_FALSE;
  glGetProgramiv(linked, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    error = std::string(label) + ": link failed: " + infoLog(linked, true);
    glDeleteProgram(linked);
    return Program();
  }
  glkit::label(GL_PROGRAM, linked, label);
  return Program(linked);
}

void label(GLenum identifier, GLuint name, std::string_view text) {
  if (text.empty() || name == 0) return;
  glObjectLabel(identifier, name, static_cast<GLsizei>(text.size()), text.data());
}

}  // namespace glkit
