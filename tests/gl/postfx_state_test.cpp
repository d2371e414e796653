// The plugin drops into a host frame without disturbing it: every piece of GL state a host may
// have set is exactly as it was after dispatch(), whether the pass ran, was skipped or failed.
#include <gtest/gtest.h>
#include <postfx/local_water.h>
#include <postfx/testing.h>

#include <functional>
#include <vector>

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

// Contexts whose passes bind textures the seabed test above does not: local water with no region
// (its lookup unit is unbound, the bug that once cleared a host's cube map on unit 7), with a
// region, and the physical model with full-resolution god rays. The host has a texture of every
// target on every unit (postfx_host_state.h).
TEST_F(PostfxStateTest, EveryTargetOnEveryUnitSurvivesEachPass) {
  postfxtest::Scene scene(postfxtest::SceneSpec{});
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  const postfxtest::FlatRegion flat = postfxtest::makeFlatRegion(16);
  const postfx::LocalWater& region = flat.region;

  struct Case {
    const char* name;
    postfx::Feature features;
    std::function<void(postfx::FrameDesc&)> edit;
  };
  const Case cases[] = {
      {"local water, no region", postfx::Feature::Caustics | postfx::Feature::LocalWater,
       [](postfx::FrameDesc&) {}},
      {"local water, one region",
       postfx::Feature::Caustics | postfx::Feature::LocalWater | postfx::Feature::GodRays,
       [&region](postfx::FrameDesc& f) {
         f.water.localWater = &region;
         f.water.localWaterCount = 1;
       }},
      {"physical model, full-res god rays",
       postfx::Feature::Caustics | postfx::Feature::GodRays | postfx::Feature::WavefrontAreaRatio,
       [](postfx::FrameDesc& f) {
         f.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
         f.caustics.gridResolution = 64;
         f.godRays.resolution = postfx::GodRayResolution::Full;
       }}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    postfx::Context* fx = nullptr;
    postfx::CreateDesc desc;
    desc.features = c.features;
    ASSERT_EQ(postfx::create(desc, fx), postfx::Result::Ok) << postfx::lastError(nullptr);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    c.edit(frame);
    host_.set();
    const GlSnapshot before = postfxtest::snapshotGlState();
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx);
    expectSameState(before, postfxtest::snapshotGlState(), c.name);
    host_.reset();
    postfx::destroy(fx);
  }
  glDeleteTextures(1, &flat.texture);
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
