#pragma once
// The refracted grid points a wavefront-area-ratio compute step writes (two vec4 per point) and
// its triangle and point draws read through an RGBA32F buffer-texture view: the window model's
// and the local water regions'. Reallocated only when the size changes, the old one freed first
// (never two allocated at once).
#include <epoxy/gl.h>

#include <cstdint>

#include <glkit/handle.h>

namespace postfx::detail {

class GridPointBuffer {
 public:
  // `points` grid points; false when the driver could not allocate them (GL_OUT_OF_MEMORY
  // leaves the buffer without bytes).
  bool ensure(std::uint64_t points, const char* label);
  void reset();
  GLuint buffer() const { return buffer_.id(); }  // for the compute step's SSBO binding
  GLuint view() const { return view_.id(); }      // for the draws' texture unit

 private:
  glkit::Buffer buffer_;
  glkit::Texture view_;
  std::uint64_t points_ = 0;
};

}  // namespace postfx::detail
