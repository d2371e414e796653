#pragma once
// Creating the plain, single-level, clamped 2D textures render targets are made of, and the
// sampler objects passes read textures with.
#include <epoxy/gl.h>

#include <string_view>

namespace glkit {

// One mip level, clamp-to-edge, `filter` for both min and mag (render targets are read
// texel-exact: GL_NEAREST unless the reader interpolates on purpose), labelled for debuggers.
GLuint createTexture2D(GLenum format, int width, int height, GLenum filter, std::string_view label);

// A sampler object with these filters and wrap on s and t, depth comparison off (a host depth
// texture may carry GL_COMPARE_REF_TO_TEXTURE; the sampler decides, not the texture), labelled.
GLuint createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap, std::string_view label);

}  // namespace glkit
