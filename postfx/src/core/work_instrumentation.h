#pragma once
// testing::CountShaderWork: every program of the context is compiled so that it counts its own
// work, which the work account (work_account.h) reads after each step. Each stage's source is
// rewritten: every texture and image read `f(args)` becomes `(postfxFetches += 1u, f(args))`,
// every atomic likewise, `discard;` flushes first, and main() is wrapped so that each invocation
// adds 1 and its counts to the counters (a buffer at kWorkCounterBinding) when it ends. Helper
// lanes of 2x2 quads write nothing, so fragments count as the fragments shaded.
#include <epoxy/gl.h>

#include <string>
#include <string_view>

namespace postfx::detail {

// The counters, as uints: per stage (vertex 0, fragment 1, compute 2) its invocations, fetches
// and atomics at 3 * stage + kWork*.
inline constexpr int kWorkVertexStage = 0;
inline constexpr int kWorkFragmentStage = 1;
inline constexpr int kWorkComputeStage = 2;
inline constexpr int kWorkInvocations = 0;
inline constexpr int kWorkFetches = 1;
inline constexpr int kWorkAtomics = 2;
inline constexpr int kWorkCounterCount = 9;
inline constexpr GLsizeiptr kWorkCounterBytes = kWorkCounterCount * sizeof(GLuint);

// The line shaderDefines() adds for a context that counts: buildPrograms() sees it and rewrites.
inline constexpr std::string_view kCountWorkDefine = "#define POSTFX_COUNT_WORK 1\n";

// Rewrites one stage's preprocessed source (glkit::ShaderLibrary::preprocess's output) to count
// its work; a stage other than vertex, fragment or compute is left as it is.
void countWork(GLenum stage, std::string& source);

}  // namespace postfx::detail
