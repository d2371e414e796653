#pragma once
// Saves the GL state update() touches and puts it back on scope exit: the host owns its state.
#include <epoxy/gl.h>

#include <array>

#include <glkit/buffer_binding.h>

namespace postfx::water::detail {

class GlStateGuard {
 public:
  GlStateGuard();
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  struct ImageUnit {
    GLint name, level, layered, layer, access, format;
  };
  GLint program_ = 0;
  std::array<ImageUnit, 3> images_{};
  GLint storageGeneric_ = 0;
  glkit::IndexedBufferBinding storage_;
};

}  // namespace postfx::water::detail
