// Bad input: each case returns its Result with a message naming the problem, leaves every GL
// state as the host set it, and draws nothing into the host's target.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_scene.h"

namespace {

using postfx::Result;

struct BadCase {
  const char* name;
  Result expected;
  const char* messageMentions;
  std::function<void(postfx::FrameDesc&)> spoil;
};

class PostfxBadInputTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  postfxtest::HostState host_;
};

TEST_F(PostfxBadInputTest, EachCaseFailsCleanly) {
  postfxtest::Scene scene(postfxtest::SceneSpec{});
  const int w = scene.spec().width, h = scene.spec().height;
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.01);
  GLuint wrongFormat = 0, wrongSize = 0, water2d = 0, bogus = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &wrongFormat);
  glTextureStorage2D(wrongFormat, 1, GL_RGBA8, w, h);
  glCreateTextures(GL_TEXTURE_2D, 1, &wrongSize);
  glTextureStorage2D(wrongSize, 1, GL_SRGB8_ALPHA8, w / 2, h);
  glCreateTextures(GL_TEXTURE_2D, 1, &water2d);
  glTextureStorage2D(water2d, 1, GL_RGBA16F, 16, 16);
  glGenTextures(1, &bogus);  // a name, never a texture
  const float nan = std::numeric_limits<float>::quiet_NaN();

  const BadCase cases[] = {
      {"target RGBA8", Result::UnsupportedFormat, "target",
       [&](postfx::FrameDesc& f) {
         f.target = {wrongFormat, 0};
       }},
      {"declared format lies", Result::UnsupportedFormat, "depth",
       [&](postfx::FrameDesc& f) { f.depth.format = GL_DEPTH_COMPONENT24; }},
      {"normal in a depth slot", Result::UnsupportedFormat, "depth",
       [&](postfx::FrameDesc& f) { f.depth = f.normal; }},
      {"albedo half size", Result::SizeMismatch, "albedo",
       [&](postfx::FrameDesc& f) {
         f.albedo = {wrongSize, 0};
       }},
      {"missing normal", Result::MissingTexture, "normal",
       [&](postfx::FrameDesc& f) { f.normal = {}; }},
      {"generated but unbound name", Result::MissingTexture, "albedo",
       [&](postfx::FrameDesc& f) {
         f.albedo = {bogus, 0};
       }},
      {"missing water", Result::MissingTexture, "water",
       [&](postfx::FrameDesc& f) { f.water.texture = {}; }},
      {"2D water for an array context", Result::UnsupportedFormat, "water",
       [&](postfx::FrameDesc& f) {
         f.water.texture = {water2d, 0};
       }},
      {"more cascades than layers", Result::SizeMismatch, "cascade",
       [&](postfx::FrameDesc& f) { f.water.cascadeCount = 3; }},
      {"NaN tau", Result::InvalidArgument, "tau",
       [&](postfx::FrameDesc& f) { f.caustics.tau = nan; }},
      {"NaN intensity", Result::InvalidArgument, "intensity",
       [&](postfx::FrameDesc& f) { f.caustics.intensity = nan; }},
      {"NaN reflection weight", Result::InvalidArgument, "reflectionWeight",
       [&](postfx::FrameDesc& f) { f.caustics.reflectionWeight = nan; }},
      {"NaN camera", Result::InvalidArgument, "camera.position",
       [&](postfx::FrameDesc& f) { f.camera.position.x = std::nan(""); }},
      {"NaN water level", Result::InvalidArgument, "water.level",
       [&](postfx::FrameDesc& f) { f.water.level = std::nan(""); }},
      {"zero sun", Result::InvalidArgument, "sun.direction",
       [&](postfx::FrameDesc& f) { f.sun.direction = glm::dvec3(0.0); }},
      {"ior below 1", Result::InvalidArgument, "ior",
       [&](postfx::FrameDesc& f) { f.water.ior = 0.5f; }},
      {"zero tile", Result::InvalidArgument, "tileSize",
       [&](postfx::FrameDesc& f) { f.water.tileSize[1] = 0.0; }},
      {"scaled view", Result::InvalidArgument, "camera.view",
       [&](postfx::FrameDesc& f) { f.camera.view[0][0] *= 2.0f; }},
      {"orthographic projection", Result::InvalidArgument, "projection",
       [&](postfx::FrameDesc& f) { f.camera.projection = glm::dmat4(1.0); }},
  };

  postfx::Context* fx = nullptr;
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::Caustics | postfx::testing::RawCausticOutput;
  ASSERT_EQ(postfx::create(desc, fx), Result::Ok) << postfx::lastError(nullptr);
  const glm::vec4 marker(0.125f, 0.25f, 0.5f, 1.0f);
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.name);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
    c.spoil(frame);
    scene.clearTarget(marker);
    host_.set();
    const postfxtest::GlSnapshot before = postfxtest::snapshotGlState();
    EXPECT_EQ(postfx::dispatch(*fx, frame), c.expected) << postfx::lastError(fx);
    EXPECT_NE(std::string(postfx::lastError(fx)).find(c.messageMentions), std::string::npos)
        << "message: " << postfx::lastError(fx);
    const postfxtest::GlSnapshot after = postfxtest::snapshotGlState();
    for (const auto& [name, value] : before) EXPECT_EQ(value, after.at(name)) << name;
    host_.reset();
    expectNoGlErrors(c.name);
    for (const glm::vec4& texel : postfxtest::readRgba(scene.target, w, h)) {
      ASSERT_EQ(texel, marker) << "something was drawn";
    }
  }
  EXPECT_EQ(postfx::stats(*fx).framesDispatched, 0u);

  // ShadowMask without a shadow map is a missing texture too.
  postfx::Context* shadowed = nullptr;
  desc.features = postfx::Feature::Caustics | postfx::Feature::ShadowMask;
  ASSERT_EQ(postfx::create(desc, shadowed), Result::Ok) << postfx::lastError(nullptr);
  EXPECT_EQ(postfx::dispatch(*shadowed, postfxtest::makeFrame(scene, water, 2)),
            Result::MissingTexture);
  EXPECT_NE(std::string(postfx::lastError(shadowed)).find("shadow"), std::string::npos);

  // A frame with more cascades than the context was created with lookups for.
  postfx::Context* oneCascade = nullptr;
  desc.features = postfx::Feature::Caustics;
  desc.maxWaterCascades = 1;
  ASSERT_EQ(postfx::create(desc, oneCascade), Result::Ok) << postfx::lastError(nullptr);
  scene.clearTarget(marker);
  EXPECT_EQ(postfx::dispatch(*oneCascade, postfxtest::makeFrame(scene, water, 2)),
            Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(oneCascade)).find("maxWaterCascades"), std::string::npos)
      << postfx::lastError(oneCascade);
  EXPECT_EQ(postfx::stats(*oneCascade).framesDispatched, 0u);
  for (const glm::vec4& texel : postfxtest::readRgba(scene.target, w, h)) {
    ASSERT_EQ(texel, marker) << "something was drawn";
  }

  postfx::destroy(oneCascade);
  postfx::destroy(shadowed);
  postfx::destroy(fx);
  const GLuint textures[] = {water, wrongFormat, wrongSize, water2d, bogus};
  glDeleteTextures(5, textures);
}

TEST_F(PostfxBadInputTest, CreateRejectsUnknownAndInvalid) {
  postfx::Context* fx = reinterpret_cast<postfx::Context*>(0x1);
  postfx::CreateDesc desc;
  desc.features = static_cast<postfx::Feature>(1u << 14);
  EXPECT_EQ(postfx::create(desc, fx), Result::InvalidArgument);
  EXPECT_EQ(fx, nullptr);
  EXPECT_NE(std::string(postfx::lastError(nullptr)).find("unknown feature"), std::string::npos);
  // The volume caustics draw the object caustics' rays: alone they are refused.
  desc.features = postfx::Feature::VolumeCaustics | postfx::Feature::GodRays;
  EXPECT_EQ(postfx::create(desc, fx), Result::InvalidArgument);
  EXPECT_EQ(fx, nullptr);
  EXPECT_NE(std::string(postfx::lastError(nullptr)).find("VolumeCaustics needs ObjectCaustics"),
            std::string::npos);
  desc.features = postfx::Feature::Caustics;
  desc.depthConvention = static_cast<postfx::DepthConvention>(7);
  EXPECT_EQ(postfx::create(desc, fx), Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(nullptr)).find("depthConvention"), std::string::npos);
  desc.depthConvention = postfx::DepthConvention::ReverseZ;
  for (int slots : {0, postfx::kMaxCascades + 1}) {
    desc.maxWaterCascades = slots;
    EXPECT_EQ(postfx::create(desc, fx), Result::InvalidArgument);
    EXPECT_NE(std::string(postfx::lastError(nullptr)).find("maxWaterCascades"), std::string::npos);
  }
  desc.maxWaterCascades = postfx::kMaxCascades;
  desc.normalEncoding = static_cast<postfx::NormalEncoding>(-1);
  EXPECT_EQ(postfx::create(desc, fx), Result::InvalidArgument);
  EXPECT_STREQ(postfx::toString(Result::SizeMismatch), "SizeMismatch");
}

}  // namespace
