#pragma once
// An indexed buffer binding point (uniform or shader-storage) as the host left it, so a library
// that binds its own buffer there can put the host's back exactly: as a range when the host
// bound a range, whole otherwise.
#include <epoxy/gl.h>

namespace glkit {

struct IndexedBufferBinding {
  GLenum target = GL_UNIFORM_BUFFER;  // GL_UNIFORM_BUFFER or GL_SHADER_STORAGE_BUFFER
  GLuint index = 0;
  GLint buffer = 0;
  GLint64 start = 0, size = 0;

  static IndexedBufferBinding save(GLenum target, GLuint index);
  // Note: glBindBufferBase/Range also replace the generic binding of `target`; restore that
  // after every indexed one.
  void restore() const;
};

}  // namespace glkit
