#pragma once
// Names for the GL enums the plugin's messages mention (texture formats and targets), so a
// refusal says "GL_RGBA8" rather than "0x8058".
#include <epoxy/gl.h>

#include <string>

namespace postfx::detail {

// "GL_RGBA16F" for a known format or target, else the value in hex ("0x1234").
std::string glEnumName(GLenum value);

}  // namespace postfx::detail
