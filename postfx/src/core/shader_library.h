#pragma once
// The plugin's GLSL, embedded at build time (cmake/EmbedShaders.cmake), and the one way every
// pass builds its programs from it.
#include <initializer_list>
#include <string>
#include <string_view>

#include <glkit/program.h>
#include <glkit/shader_library.h>
#include <postfx/result.h>

namespace postfx::detail {

const glkit::ShaderLibrary& shaderLibrary();

// The vertex stage of every full-screen pass: one triangle covering the viewport.
inline constexpr glkit::ShaderStage kFullScreenVertex{GL_VERTEX_SHADER,
                                                      "postfx/common/fullscreen.vert"};

// One program of a pass: where it goes, its debugger label, its stages, and #defines appended
// to the context's (variants of one source).
struct ProgramRequest {
  glkit::Program& out;
  std::string_view label;
  std::initializer_list<glkit::ShaderStage> stages;
  std::string_view extraDefines = {};
};

// Builds a pass's programs with the context's `defines`, all or none: on a failure no `out`
// changes, `error` holds the driver's log and the result is ShaderCompileFailed (a context
// whose create failed, or a model whose first use failed, keeps nothing half built).
Result buildPrograms(std::string_view defines, std::initializer_list<ProgramRequest> requests,
                     std::string& error);

}  // namespace postfx::detail
