#include <vector>

#include "core/shader_library.h"

namespace postfx::detail {

Result buildPrograms(std::string_view defines, std::initializer_list<ProgramRequest> requests,
                     std::string& error) {
  std::vector<glkit::Program> built;
  built.reserve(requests.size());
  for (const ProgramRequest& request : requests) {
    const std::string all = std::string(defines) + std::string(request.extraDefines);
    built.push_back(
        glkit::buildProgram(shaderLibrary(), request.stages, all, request.label, error));
    if (!built.back()) return Result::ShaderCompileFailed;
  }
  auto program = built.begin();
  for (const ProgramRequest& request : requests) request.out = std::move(*program++);
  return Result::Ok;
}

}  // namespace postfx::detail
