#pragma once
// The sized format a host texture really holds. GL reports an unsized allocation
// (glTexImage2D(..., GL_RGBA, ..., GL_UNSIGNED_BYTE, ...), as tutorials write it) by the unsized
// name it was asked for; the driver still picked a sized one, which the texture's component
// sizes and types give back. Validation accepts an unsized texture exactly when that sized
// format is one it accepts, so a host never has to reallocate a texture that already works.
#include <epoxy/gl.h>

#include <initializer_list>
#include <string>

namespace postfx::detail {

// GL_RED, GL_RG, GL_RGB, GL_RGBA, GL_DEPTH_COMPONENT, GL_DEPTH_STENCIL and the sRGB/unsized
// integer names: a format that says which components, not their sizes.
bool isUnsizedFormat(GLenum format);

// `reported` when it is sized; else the sized format whose component sizes and types level 0
// of `texture` has (GL_RGBA + 8-bit unsigned normalized -> GL_RGBA8), or 0 when none matches.
GLenum effectiveSizedFormat(GLuint texture, GLenum reported);

// "GL_RGBA16F, GL_RGBA32F or GL_R11F_G11F_B10F": a list of accepted formats as a message
// names them.
std::string formatList(std::initializer_list<GLenum> formats);

}  // namespace postfx::detail
