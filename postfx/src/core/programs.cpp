#include <vector>

#include "core/shader_library.h"
#include "core/work_instrumentation.h"

namespace postfx::detail {

Result buildPrograms(std::string_view defines, std::initializer_list<ProgramRequest> requests,
                     std::string& error) {
  std::vector<glkit::Program> built;
  built.reserve(requests.size());
  // testing::CountShaderWork: the context's shaders count their own work.
  const glkit::SourceFilter counting =
      defines.find(kCountWorkDefine) != std::string_view::npos ? countWork : glkit::SourceFilter{};
  for (const ProgramRequest& request : requests) {
    const std::string all = std::string(defines) + std::string(request.extraDefines);
    built.push_back(
        glkit::buildProgram(shaderLibrary(), request.stages, all, request.label, error, counting));
    if (!built.back()) return Result::ShaderCompileFailed;
  }
  auto program = built.begin();
  for (const ProgramRequest& request : requests) request.out = std::move(*program++);
  return Result::Ok;
}

}  // namespace postfx::detail
