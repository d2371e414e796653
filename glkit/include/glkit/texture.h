#pragma once
// Creating the plain, single-level, clamped 2D textures render targets are made of.
#include <epoxy/gl.h>

#include <string_view>

namespace glkit {

// One mip level, clamp-to-edge, `filter` for both min and mag (render targets are read
// texel-exact: GL_NEAREST unless the reader interpolates on purpose), labelled for debuggers.
GLuint createTexture2D(GLenum format, int width, int height, GLenum filter, std::string_view label);

}  // namespace glkit
