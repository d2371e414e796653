#include "seabed_caustics/grid_point_buffer.h"

#include <string>

namespace postfx::detail {

bool GridPointBuffer::ensure(std::uint64_t points, const char* label) {
  const GLsizeiptr bytes = GLsizeiptr(points * 2 * 16);
  if (!buffer_ || points_ != points) {
    reset();
    buffer_ = glkit::createBuffer(bytes, nullptr, 0, label);
    view_ = glkit::createTexture(GL_TEXTURE_BUFFER, std::string(label) + "_view");
    glTextureBuffer(view_.id(), GL_RGBA32F, buffer_.id());
    points_ = points;
  }
  GLint64 stored = 0;
  glGetNamedBufferParameteri64v(buffer_.id(), GL_BUFFER_SIZE, &stored);
  if (stored < GLint64(bytes) || stored <= 0) {
    points_ = 0;  // tried again next frame
    return false;
  }
  return true;
}

void GridPointBuffer::reset() {
  view_.reset();
  buffer_.reset();
  points_ = 0;
}

}  // namespace postfx::detail
