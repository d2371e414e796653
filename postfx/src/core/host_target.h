#pragma once
// Every pass draws into the host's HDR target through a framebuffer of its own; the target is
// attached per dispatch because the host may hand a different texture each frame.
#include <epoxy/gl.h>

#include <string>

namespace postfx::detail {

// Attaches `target` (mip 0) as colour 0 of `framebuffer`. Returns false with a message naming
// `pass` when the driver reports the framebuffer incomplete.
bool attachHostTarget(GLuint framebuffer, GLuint target, const char* pass, std::string& error);

}  // namespace postfx::detail
