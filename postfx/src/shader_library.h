#pragma once
// The plugin's GLSL, embedded at build time (cmake/EmbedShaders.cmake).
#include <glkit/shader_library.h>

namespace postfx::detail {
const glkit::ShaderLibrary& shaderLibrary();
}
