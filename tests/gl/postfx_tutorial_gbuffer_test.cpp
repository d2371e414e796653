// A host started from the most common deferred-shading tutorial (LearnOpenGL's 8.1 G-buffer):
// unsized glTexImage2D allocations, a depth renderbuffer, world normals in RGBA16F, a position
// buffer, lighting into the default (LDR) framebuffer. docs/integration.md, "From a tutorial's
// G-buffer", says what to change; this test walks that path: each step the section names is
// refused with a message saying the fix, and after the fixes the frame draws the same light as
// the same scene in sized textures.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfx::Result;

class PostfxTutorialGbufferTest : public testsupport::GlTest {};

// glTexImage2D as the tutorial writes it: an unsized (or sized) internal format with data.
GLuint tutorialTexture(GLint internalFormat, GLenum format, GLenum type, int w, int h,
                       const void* data) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexImage2D(GL_TEXTURE_2D, 0, internalFormat, w, h, 0, format, type, data);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glBindTexture(GL_TEXTURE_2D, 0);
  return t;
}

TEST_F(PostfxTutorialGbufferTest, ATutorialsGbufferDrawsAfterTheDocumentedFixes) {
  postfxtest::SceneSpec spec;
  spec.width = 96;
  spec.height = 54;
  spec.albedo = glm::vec3(1.0f);
  const postfxtest::Scene scene(spec);
  const int w = spec.width, h = spec.height;
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.02);

  // The scene's G-buffer as the tutorial stores it: depth as floats, world normals in RGBA16F,
  // albedo in 8-bit unsized RGBA.
  std::vector<float> depth(static_cast<size_t>(w) * h);
  glGetTextureImage(scene.depth, 0, GL_DEPTH_COMPONENT, GL_FLOAT, int(depth.size() * 4),
                    depth.data());
  std::vector<glm::vec4> normals(static_cast<size_t>(w) * h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      normals[static_cast<size_t>(y) * w + x] = glm::vec4(glm::vec3(scene.truth(x, y).normal), 0);
  const std::vector<unsigned char> white(static_cast<size_t>(w) * h * 4, 255);

  const GLuint normal = tutorialTexture(GL_RGBA16F, GL_RGBA, GL_FLOAT, w, h, normals.data());
  const GLuint albedo = tutorialTexture(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, w, h, white.data());
  const GLuint ldrTarget = tutorialTexture(GL_RGBA, GL_RGBA, GL_UNSIGNED_BYTE, w, h, nullptr);
  GLuint renderbuffer = 0;
  glGenRenderbuffers(1, &renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, renderbuffer);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT, w, h);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);

  postfx::CreateDesc desc;
  desc.features = postfx::Feature::Caustics;
  desc.normalEncoding = postfx::NormalEncoding::WorldXyz;  // the tutorial's normals
  postfx::Context* fx = nullptr;
  ASSERT_EQ(postfx::create(desc, fx), Result::Ok) << postfx::lastError(nullptr);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  frame.normal = {normal, 0};
  frame.albedo = {albedo, 0};

  // 1. An LDR target: refused, naming the HDR formats and how to allocate one.
  frame.depth = {scene.depth, 0};
  frame.target = {ldrTarget, 0};
  EXPECT_EQ(postfx::dispatch(*fx, frame), Result::UnsupportedFormat);
  std::string message = postfx::lastError(fx);
  EXPECT_EQ(message.rfind("target: internal format GL_RGBA (unsized; its components are "
                          "GL_RGBA8's) is not accepted here (GL_RGBA16F, GL_RGBA32F or "
                          "GL_R11F_G11F_B10F); allocate it as one with glTextureStorage2D(texture, "
                          "1, GL_RGBA16F, width, height)",
                          0),
            0u)
      << message;

  // 2. The depth renderbuffer (its name is also the unsized albedo texture's in this context's
  // separate namespaces, or no texture at all): refused, saying a texture is needed.
  const GLuint hdrTarget = tutorialTexture(GL_RGBA16F, GL_RGBA, GL_FLOAT, w, h, nullptr);
  frame.target = {hdrTarget, 0};
  frame.depth = {renderbuffer, GL_DEPTH_COMPONENT};
  EXPECT_NE(postfx::dispatch(*fx, frame), Result::Ok);
  message = postfx::lastError(fx);
  EXPECT_NE(message.find("renderbuffer"), std::string::npos) << message;
  EXPECT_NE(message.find("glNamedFramebufferTexture"), std::string::npos) << message;
  EXPECT_EQ(message.find("0x"), std::string::npos) << "a format in hex: " << message;

  // 3. The fixes: depth as an (unsized) depth texture, the lighting into an HDR texture. The
  // unsized albedo and depth are accepted for the sized formats they hold.
  const GLuint depthTexture =
      tutorialTexture(GL_DEPTH_COMPONENT, GL_DEPTH_COMPONENT, GL_FLOAT, w, h, depth.data());
  frame.depth = {depthTexture, GL_DEPTH_COMPONENT};
  scene.clearTarget(glm::vec4(0.0f));
  glClearTexImage(hdrTarget, 0, GL_RGBA, GL_FLOAT, nullptr);
  ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx);
  std::vector<glm::vec4> tutorial(static_cast<size_t>(w) * h);
  glGetTextureImage(hdrTarget, 0, GL_RGBA, GL_FLOAT, int(tutorial.size() * 16), tutorial.data());

  // The same frame in the scene's own sized textures (albedo 1 in sRGB = 1 linear).
  postfx::CreateDesc sizedDesc;
  sizedDesc.features = postfx::Feature::Caustics;
  postfx::Context* sized = nullptr;
  ASSERT_EQ(postfx::create(sizedDesc, sized), Result::Ok);
  const postfx::FrameDesc reference = postfxtest::makeFrame(scene, water, 3);
  scene.clearTarget(glm::vec4(0.0f));
  ASSERT_EQ(postfx::dispatch(*sized, reference), Result::Ok) << postfx::lastError(sized);
  const std::vector<glm::vec4> expected = postfxtest::readRgba(scene.target, w, h);
  double sum = 0.0, diff = 0.0;
  int lit = 0;
  for (size_t i = 0; i < expected.size(); ++i) {
    sum += double(expected[i].r);
    diff += std::abs(double(tutorial[i].r) - double(expected[i].r));
    lit += expected[i].r > 0.0f ? 1 : 0;
  }
  EXPECT_GT(lit, w * h / 4) << "the reference draws caustic light";
  // The two differ only by the normals' half floats against the octahedral encoding.
  EXPECT_LT(diff / sum, 0.01) << "the tutorial's G-buffer draws the same light";
  std::printf("tutorial G-buffer vs sized: mean |difference| %.2e of the light\n", diff / sum);

  postfx::destroy(sized);
  postfx::destroy(fx);
  const GLuint textures[] = {normal, albedo, ldrTarget, hdrTarget, depthTexture, water};
  glDeleteTextures(6, textures);
  glDeleteRenderbuffers(1, &renderbuffer);
}

}  // namespace
