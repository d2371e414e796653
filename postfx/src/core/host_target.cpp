#include "core/host_target.h"

namespace postfx::detail {

bool attachHostTarget(GLuint framebuffer, GLuint target, const char* pass, std::string& error) {
  glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, target, 0);
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
  if (status == GL_FRAMEBUFFER_COMPLETE) return true;
  error = std::string("target: ") + pass +
          " framebuffer with the HDR target is incomplete (status " + std::to_string(status) + ")";
  return false;
}

}  // namespace postfx::detail
