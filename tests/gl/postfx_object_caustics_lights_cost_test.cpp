// What a local light's object caustics cost: against a fair floor that draws
// the same caster (front and back maps), splats the same number of points with the same sprite
// and composites the same map, with no math; and linear in the lights that reach a caster.
// Timed on the GPU in one process, interleaved (GL_TIME_ELAPSED around each, the GPU drained
// before each as BenchmarkFloor does): the ratios are what to read, never the milliseconds.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_fixture.h"
#include "postfx_object_caustics_lights_util.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

GLuint compile(GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  EXPECT_EQ(ok, GL_TRUE);
  return shader;
}

GLuint link(const char* vertex, const char* fragment) {
  const GLuint program = glCreateProgram();
  const GLuint v = compile(GL_VERTEX_SHADER, vertex), f = compile(GL_FRAGMENT_SHADER, fragment);
  glAttachShader(program, v);
  glAttachShader(program, f);
  glLinkProgram(program);
  glDeleteShader(v);
  glDeleteShader(f);
  return program;
}

// The floor: the caster maps (the mesh drawn twice into two RGBA32F targets and a depth buffer,
// constant outputs, at the size the light's view gives it), one point per grid cell the caster
// covers with the splats' sprite at splat radius 1 (7 texels) added into a mapSize^2 RGBA32F
// map, and a full-screen pass that reads the map and adds 0 into the target. Not in it: the
// trace's compute dispatch over the grid and every bit of optics.
class LightFloor {
 public:
  // disk: radius (clip units) of the caster's disk in the light's view: the cells whose rays
  // the real pass splats.
  LightFloor(int gridSize, int mapSize, GLuint target, float disk)
      : grid_(gridSize), map_(mapSize), disk_(disk) {
    casterProgram_ = link(
        "#version 450 core\nlayout(location=0) in vec3 p; layout(location=0) uniform mat4 m;\n"
        "void main() { gl_Position = m * vec4(p, 1.0); }\n",
        "#version 450 core\nlayout(location=0) out vec4 a; layout(location=1) out vec4 b;\n"
        "void main() { a = vec4(1.0); b = vec4(0.5); }\n");
    splatProgram_ = link(
        "#version 450 core\nlayout(location=0) uniform int size;\n"
        "layout(location=1) uniform float disk;\n"
        "void main() { ivec2 c = ivec2(gl_VertexID % size, gl_VertexID / size);\n"
        "  vec2 p = (vec2(c) + 0.5) / float(size) * 2.0 - 1.0;\n"
        "  gl_Position = dot(p, p) < disk * disk ? vec4(p * 0.5, 0.5, 1.0) : vec4(2.0);\n"
        "  gl_PointSize = 7.0; }\n",
        "#version 450 core\nlayout(location=0) out vec4 o; void main() { o = vec4(1e-6); }\n");
    compositeProgram_ = link(
        "#version 450 core\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
        "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0); }\n",
        "#version 450 core\nlayout(binding=0) uniform sampler2D map; layout(location=0) out vec4 "
        "o;\n"
        "void main() { o = vec4(textureLod(map, gl_FragCoord.xy / 512.0, 0.0).rgb * 0.0, 0.0); "
        "}\n");
    glCreateTextures(GL_TEXTURE_2D, 4, textures_);
    glTextureStorage2D(textures_[0], 1, GL_RGBA32F, grid_, grid_);
    glTextureStorage2D(textures_[1], 1, GL_RGBA32F, grid_, grid_);
    glTextureStorage2D(textures_[2], 1, GL_DEPTH_COMPONENT32F, grid_, grid_);
    glTextureStorage2D(textures_[3], 1, GL_RGBA32F, map_, map_);
    glCreateFramebuffers(3, fbos_);
    glNamedFramebufferTexture(fbos_[0], GL_COLOR_ATTACHMENT0, textures_[0], 0);
    glNamedFramebufferTexture(fbos_[0], GL_COLOR_ATTACHMENT1, textures_[1], 0);
    glNamedFramebufferTexture(fbos_[0], GL_DEPTH_ATTACHMENT, textures_[2], 0);
    const GLenum two[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(fbos_[0], 2, two);
    glNamedFramebufferTexture(fbos_[1], GL_COLOR_ATTACHMENT0, textures_[3], 0);
    glNamedFramebufferTexture(fbos_[2], GL_COLOR_ATTACHMENT0, target, 0);
    glCreateVertexArrays(1, &vao_);
    glCreateQueries(GL_TIME_ELAPSED, 1, &query_);
  }
  ~LightFloor() {
    glDeleteProgram(casterProgram_);
    glDeleteProgram(splatProgram_);
    glDeleteProgram(compositeProgram_);
    glDeleteTextures(4, textures_);
    glDeleteFramebuffers(3, fbos_);
    glDeleteVertexArrays(1, &vao_);
    glDeleteQueries(1, &query_);
  }

  // GPU milliseconds of one floor frame over `mesh` seen through `clip`.
  double run(const GlMesh& mesh, const glm::mat4& clip, int width, int height) {
    glFinish();
    glBeginQuery(GL_TIME_ELAPSED, query_);
    glBindVertexArray(vao_);
    glVertexArrayVertexBuffer(vao_, 0, mesh.vertexBuffer, 0, 24);
    glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_, 0, 0);
    glEnableVertexArrayAttrib(vao_, 0);
    glVertexArrayElementBuffer(vao_, mesh.indexBuffer);
    glUseProgram(casterProgram_);
    glProgramUniformMatrix4fv(casterProgram_, 0, 1, GL_FALSE, &clip[0][0]);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos_[0]);
    glViewport(0, 0, grid_, grid_);
    glEnable(GL_DEPTH_TEST);
    const float zero[4] = {0, 0, 0, 0};
    for (int side = 0; side < 2; ++side) {
      const float depth = side == 0 ? 1.0f : 0.0f;
      glClearNamedFramebufferfv(fbos_[0], GL_COLOR, 0, zero);
      glClearNamedFramebufferfv(fbos_[0], GL_COLOR, 1, zero);
      glClearNamedFramebufferfv(fbos_[0], GL_DEPTH, 0, &depth);
      glDepthFunc(side == 0 ? GL_LESS : GL_GREATER);
      glDrawElements(GL_TRIANGLES, GLsizei(mesh.indexCount), GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearNamedFramebufferfv(fbos_[1], GL_COLOR, 0, zero);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos_[1]);
    glViewport(0, 0, map_, map_);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glUseProgram(splatProgram_);
    glProgramUniform1i(splatProgram_, 0, grid_);
    glProgramUniform1f(splatProgram_, 1, disk_);
    glDrawArrays(GL_POINTS, 0, grid_ * grid_);
    glDisable(GL_PROGRAM_POINT_SIZE);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos_[2]);
    glViewport(0, 0, width, height);
    glBindTextureUnit(0, textures_[3]);
    glUseProgram(compositeProgram_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisable(GL_BLEND);
    glEndQuery(GL_TIME_ELAPSED);
    GLuint64 ns = 0;
    glGetQueryObjectui64v(query_, GL_QUERY_RESULT, &ns);
    glBindTextureUnit(0, 0);
    glUseProgram(0);
    glBindVertexArray(0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    return double(ns) * 1e-6;
  }

 private:
  int grid_, map_;
  float disk_;
  GLuint casterProgram_ = 0, splatProgram_ = 0, compositeProgram_ = 0;
  GLuint textures_[4] = {}, fbos_[3] = {}, vao_ = 0, query_ = 0;
};

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

class PostfxObjectCausticsLightsCostTest : public testsupport::GlTest {};

TEST_F(PostfxObjectCausticsLightsCostTest, CostPerLightAgainstAFairFloorIsLinear) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(0.5, 64, 32);
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.0, 0.0}), {});
  const glm::dvec3 position(0.0, 3.0, 0.0), down(0.0, -1.0, 0.0);
  LightReceiverMap receivers(position, down, 40.0, 0.0, 512);
  const postfx::LocalLight light =
      makeLight(postfx::LocalLightType::Point, position, down, receivers.desc());
  const std::vector<postfx::LocalLight> lights(4, light);
  const postfx::ObjectCausticsSettings s;  // defaults: grid 256, map 512
  // The light 2 m from the centre of the sphere (R 0.5) fits its view to the sphere's box: the
  // box's top corners, 1.5 m below it and 0.5 m to the side, set its half side (tan 1/3, 2 %
  // room), and the sphere's disk spans tan(asin(R / 2)) / (1.02 / 3) = 0.76 of it.
  const float disk = 0.76f;
  LightFloor floor(s.gridSize, s.mapSize, host.scene.target, disk);
  const int frames = 8;
  double oneLight = 0.0, oneLightRatio = 0.0;
  for (int count : {1, 2, 4}) {
    // A context of its own per count: a light's median counts the frames it was skipped in.
    ContextPtr fx = makeLightContext(4, postfx::testing::BenchmarkFloor);
    const postfx::FrameDesc frame = lightsOnlyFrame(host, &caster, 1, lights.data(), count, s);
    for (int f = 0; f < 2; ++f) ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);  // warm-up
    std::vector<double> floorMs, lightMs;
    // The light's view of the sphere, as the floor's caster clip (its size, not its math,
    // sets the floor's cost).
    const glm::mat4 clip = glm::mat4(
        glm::scale(glm::dmat4(1.0), glm::dvec3(double(disk) / 0.5, double(disk) / 0.5, 0.1)));
    for (int f = 0; f < frames; ++f) {
      ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
      floorMs.push_back(floor.run(mesh, clip, host.scene.spec().width, host.scene.spec().height));
    }
    for (int f = 0; f < postfx::kTimerRingDepth; ++f) {  // let the last frames resolve
      glFinish();
      ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
    }
    const postfx::FrameStats& stats = postfx::stats(*fx);
    double total = 0.0;
    for (int i = 0; i < count; ++i) total += stats.objectLight(i).medianMs;
    const double floorMedian = median(floorMs);
    // Per light, as a ratio to the floor timed in the same frames: what survives the load.
    const double ratio = total / count / floorMedian;
    if (count == 1) {
      oneLight = total;
      oneLightRatio = ratio;
    }
    std::printf(
        "%d light(s): lights %.2f ms in all (%.2f per light), fair floor %.2f ms: %.2fx the "
        "floor per light; %.2fx one light's cost\n",
        count, total, total / count, floorMedian, ratio, total / oneLight);
    for (int i = 0; i < count; ++i) EXPECT_GT(stats.objectLight(i).medianMs, 0.0);
    EXPECT_GT(floorMedian, 0.0);
    // Linear: each light costs about what one alone does, against the floor of the same frames.
    // Loose bounds: llvmpipe shares the CPU with whatever else runs, and a load spike during
    // one count's frames moved the lights' total from 3x to 14x one light's while the floor
    // moved with it (per-light ratio 2.06 against 4.90 alone). Quiet runs: 0.67-0.76 for four
    // lights against one (the first light of a frame costs more).
    EXPECT_GT(ratio / oneLightRatio, 0.3);
    EXPECT_LT(ratio / oneLightRatio, 3.0);
  }
}

}  // namespace
