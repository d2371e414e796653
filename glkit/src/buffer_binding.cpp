#include <glkit/buffer_binding.h>

namespace glkit {

IndexedBufferBinding IndexedBufferBinding::save(GLenum target, GLuint index) {
  const bool storage = target == GL_SHADER_STORAGE_BUFFER;
  IndexedBufferBinding binding;
  binding.target = target;
  binding.index = index;
  glGetIntegeri_v(storage ? GL_SHADER_STORAGE_BUFFER_BINDING : GL_UNIFORM_BUFFER_BINDING, index,
                  &binding.buffer);
  glGetInteger64i_v(storage ? GL_SHADER_STORAGE_BUFFER_START : GL_UNIFORM_BUFFER_START, index,
                    &binding.start);
  glGetInteger64i_v(storage ? GL_SHADER_STORAGE_BUFFER_SIZE : GL_UNIFORM_BUFFER_SIZE, index,
                    &binding.size);
  return binding;
}

void IndexedBufferBinding::restore() const {
  const auto name = static_cast<GLuint>(buffer);
  if (name == 0 || size <= 0) {
    glBindBufferBase(target, index, name);
  } else {
    glBindBufferRange(target, index, name, static_cast<GLintptr>(start),
                      static_cast<GLsizeiptr>(size));
  }
}

}  // namespace glkit
