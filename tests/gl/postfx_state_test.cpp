// The plugin drops into a host frame without disturbing it: every piece of GL state a host may
// have set is exactly as it was after dispatch(), whether the pass ran, was skipped or failed.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_scene.h"

namespace {

using postfxtest::GlSnapshot;

void expectSameState(const GlSnapshot& before, const GlSnapshot& after, const char* when) {
  for (const auto& [name, value] : before) {
    auto it = after.find(name);
    ASSERT_NE(it, after.end()) << name;
    EXPECT_EQ(value, it->second) << when << ": GL state '" << name << "' changed";
  }
}

class PostfxStateTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  postfxtest::HostState host_;
};

TEST_F(PostfxStateTest, EveryHostStateSurvivesDispatch) {
  postfxtest::Scene scene(postfxtest::SceneSpec{});
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  postfx::Context* fx = nullptr;
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::Caustics | postfx::testing::RawCausticOutput |
                  postfx::testing::BenchmarkFloor;
  ASSERT_EQ(postfx::create(desc, fx), postfx::Result::Ok) << postfx::lastError(nullptr);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);

  host_.set();
  const GlSnapshot before = postfxtest::snapshotGlState();
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx);
  expectSameState(before, postfxtest::snapshotGlState(), "pass ran");

  frame.caustics.enabled = false;  // the skip path
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx);
  expectSameState(before, postfxtest::snapshotGlState(), "pass skipped");

  frame.caustics.enabled = true;
  frame.caustics.tau = -1.0f;  // the error path
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument);
  expectSameState(before, postfxtest::snapshotGlState(), "dispatch failed");
  host_.reset();

  // And the pass did draw while the host's unusual state was set.
  // (The skip cleared the raw output, so look at the light added to the target.)
  double sum = 0.0;
  for (const glm::vec4& p :
       postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height))
    sum += double(p.r);
  EXPECT_GT(sum, 1.0);
  postfx::destroy(fx);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxStateTest, CreateAndDestroyBindNothing) {
  host_.set();
  const GlSnapshot before = postfxtest::snapshotGlState();
  postfx::Context* fx = nullptr;
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::Caustics | postfx::Feature::ShadowMask |
                  postfx::Feature::Dispersion | postfx::testing::RawCausticOutput;
  ASSERT_EQ(postfx::create(desc, fx), postfx::Result::Ok) << postfx::lastError(nullptr);
  postfx::destroy(fx);
  expectSameState(before, postfxtest::snapshotGlState(), "create/destroy");
}

}  // namespace
