// The GLSL build of shaders/shared/gbuffer_codec.h must agree with its C++ build: the tests
// and CPU references use the C++ one and rely on it being what the shaders compute.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include <gl_fixture.h>
#include <glkit/program.h>

#include "reconstruction_cases.h"

namespace gbuffer_test {
const glkit::ShaderLibrary& shaderLibrary();
}

namespace {

struct Case {
  glm::vec4 uvDepth, xyParams, zParams, normal;
};

class GbufferShaderMirror : public testsupport::GlTest {};

TEST_F(GbufferShaderMirror, GlslAndCppReconstructAndDecodeAlike) {
  std::vector<Case> cases;
  testsupport::TestCamera camera;
  for (int convention = 0; convention < 3; ++convention) {
    const auto kind = static_cast<gbuffer::DepthConvention>(convention);
    const gbuffer::ProjectionParams params =
        gbuffer::projectionParams(testsupport::projection(camera, kind), kind);
    for (float depth : {0.999f, 0.9f, 0.5f, 0.01f, 1e-5f}) {
      for (int encoding = 0; encoding < 3; ++encoding) {
        const glm::vec3 n = glm::normalize(glm::vec3(0.2f * depth - 0.4f, -0.7f, 0.3f + depth));
        cases.push_back({glm::vec4(0.3f, 0.8f, depth, float(convention)), params.xy,
                         glm::vec4(params.z, float(encoding), 0.0f), glm::vec4(n, 0.0f)});
      }
    }
  }
  std::string error;
  const glkit::Program program = glkit::buildProgram(
      gbuffer_test::shaderLibrary(), {{GL_COMPUTE_SHADER, "gbuffer/test_reconstruct.comp"}}, "",
      "test.reconstruct", error);
  ASSERT_NE(program.id(), 0u) << error;
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  glNamedBufferStorage(buffers[0], GLsizeiptr(cases.size() * sizeof(Case)), cases.data(), 0);
  glNamedBufferStorage(buffers[1], GLsizeiptr(cases.size() * 2 * sizeof(glm::vec4)), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glUseProgram(program.id());
  glUniform1i(program.uniform("caseCount"), GLint(cases.size()));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers[0]);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers[1]);
  glDispatchCompute(GLuint((cases.size() + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<glm::vec4> results(cases.size() * 2);
  glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(results.size() * sizeof(glm::vec4)),
                          results.data());
  glUseProgram(0);
  glDeleteBuffers(2, buffers);

  double worstPosition = 0.0, worstNormal = 0.0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const Case& c = cases[i];
    const glm::vec3 view = gbuffer::shared::viewPositionFromDepth(
        glm::vec2(c.uvDepth), c.uvDepth.z, c.xyParams, glm::vec2(c.zParams), int(c.uvDepth.w));
    const int encoding = int(c.zParams.z);
    const glm::vec3 decoded = gbuffer::shared::decodeNormal(
        gbuffer::shared::encodeNormal(glm::vec3(c.normal), encoding), encoding);
    worstPosition = std::max(
        worstPosition, double(glm::distance(view, glm::vec3(results[2 * i])) / glm::length(view)));
    worstNormal =
        std::max(worstNormal, double(glm::distance(decoded, glm::vec3(results[2 * i + 1]))));
  }
  std::printf("GLSL vs C++: worst relative position difference %.2e, normal %.2e\n", worstPosition,
              worstNormal);
  // Same source; the compilers may fuse or reorder float operations: a few ulps.
  EXPECT_LT(worstPosition, 1e-5);
  EXPECT_LT(worstNormal, 1e-5);
}

}  // namespace
