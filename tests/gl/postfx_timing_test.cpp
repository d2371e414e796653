// Per-pass GPU timing: non-stalling timestamp pairs in a ring; results appear a few dispatches
// later, skipped passes report 0 ms, the floor pass is timed beside the caustics.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <string>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

class PostfxTimingTest : public testsupport::GlTest {};

TEST_F(PostfxTimingTest, ResultsArriveLaterAndSkippedPassesReportZero) {
  postfxtest::SceneSpec spec;
  spec.lookDirection = {0.0, -0.6, -1.0};
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.01);
  auto fx = postfxtest::makeContext(postfx::Feature::Caustics | postfx::testing::BenchmarkFloor);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);

  const postfx::FrameStats& s = postfx::stats(*fx);
  EXPECT_TRUE(s.pass(postfx::Pass::Caustics).present);
  EXPECT_TRUE(s.pass(postfx::Pass::Floor).present);
  EXPECT_FALSE(s.pass(postfx::Pass::GodRays).present);
  EXPECT_STREQ(postfx::toString(postfx::Pass::Floor), "floor");
  // The TileIrradiance pre-pass exists with Feature::Caustics; this frame's model (ray
  // deviation) does not run it.
  EXPECT_TRUE(s.pass(postfx::Pass::TileIrradiance).present);

  // The first dispatch cannot have read anything: its queries are read by later dispatches.
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  EXPECT_EQ(s.framesResolved, 0u);
  EXPECT_EQ(s.pass(postfx::Pass::Caustics).samples, 0u);

  for (int i = 0; i < 3; ++i) ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  EXPECT_EQ(s.framesDispatched, 5u);
  EXPECT_GE(s.framesResolved, 1u);
  EXPECT_LE(s.framesResolved + s.framesDropped, 4u) << "never more than was dispatched before";
  EXPECT_GT(s.pass(postfx::Pass::Caustics).lastMs, 0.0);
  EXPECT_GT(s.pass(postfx::Pass::Floor).lastMs, 0.0);
  EXPECT_GT(s.pass(postfx::Pass::Caustics).medianMs, 0.0);
  EXPECT_FALSE(s.pass(postfx::Pass::Caustics).skipped);
  EXPECT_TRUE(s.pass(postfx::Pass::TileIrradiance).skipped);
  EXPECT_EQ(s.pass(postfx::Pass::TileIrradiance).lastMs, 0.0);

  // Caustics disabled: both passes skipped; once those frames resolve they report 0 ms.
  frame.caustics.enabled = false;
  for (int i = 0; i < postfx::kTimerRingDepth + 1; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
    glFinish();
  }
  EXPECT_TRUE(s.pass(postfx::Pass::Caustics).skipped);
  EXPECT_EQ(s.pass(postfx::Pass::Caustics).lastMs, 0.0);
  EXPECT_TRUE(s.pass(postfx::Pass::Floor).skipped);
  EXPECT_EQ(s.pass(postfx::Pass::Floor).lastMs, 0.0);

  // A host timing the whole plugin with its own GL_TIME_ELAPSED query: elapsed queries cannot
  // nest, so the plugin falls back to timestamp pairs (no GL error, results still arrive).
  frame.caustics.enabled = true;
  GLuint hostQuery = 0;
  glCreateQueries(GL_TIME_ELAPSED, 1, &hostQuery);
  const std::uint64_t resolvedBefore = s.framesResolved;
  for (int i = 0; i < postfx::kTimerRingDepth + 1; ++i) {
    glBeginQuery(GL_TIME_ELAPSED, hostQuery);
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
    glEndQuery(GL_TIME_ELAPSED);
    glFinish();
  }
  expectNoGlErrors("host elapsed query around dispatch");
  EXPECT_GT(s.framesResolved, resolvedBefore);
  EXPECT_FALSE(s.pass(postfx::Pass::Caustics).skipped);
  glDeleteQueries(1, &hostQuery);

  // Many dispatches without ever waiting: the ring never blocks and accounts for every frame.
  frame.caustics.enabled = true;
  for (int i = 0; i < 40; ++i) ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  EXPECT_LE(s.framesDispatched - s.framesResolved - s.framesDropped,
            static_cast<std::uint64_t>(postfx::kTimerRingDepth));
  EXPECT_LE(s.pass(postfx::Pass::Caustics).samples,
            static_cast<std::uint32_t>(postfx::kTimerMedianWindow));
  glDeleteTextures(1, &water);
}

}  // namespace
