// Manual benchmark (disabled by default; run with --gtest_also_run_disabled_tests): caustics
// vs floor GPU time at 1280x720 on a synthetic underwater G-buffer. The budget is
// caustics / floor <= 2.0; the sample app's `bench` is the reference measurement.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cstdio>
#include <string>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

class PostfxBench : public testsupport::GlTest {};

TEST_F(PostfxBench, DISABLED_FloorRatioAt720p) {
  postfxtest::SceneSpec spec;
  spec.width = 1280;
  spec.height = 720;
  spec.lookDirection = {0.0, -0.35, -1.0};
  spec.sphereCenter = {2.0, 0.5, -8.0};
  postfxtest::Scene scene(spec, GL_RGBA16F);
  const GLuint water = postfxtest::makeWaterTexture(256, 3, 0.01);
  {
    auto fx = postfxtest::makeContext(postfx::Feature::Caustics | postfx::testing::BenchmarkFloor);
    const postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
    for (int i = 0; i < 40; ++i) {
      ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
      glFinish();  // benchmark only: one frame at a time so the queries time just this pass
    }
    const postfx::FrameStats& s = postfx::stats(*fx);
    const double caustics = s.pass(postfx::Pass::Caustics).medianMs,
                 floor = s.pass(postfx::Pass::Floor).medianMs;
    std::printf("1280x720 caustics %.3f ms, floor %.3f ms, floor_ratio %.2f (%u samples)\n",
                caustics, floor, caustics / floor, s.pass(postfx::Pass::Caustics).samples);
    // Not asserted: llvmpipe timings vary with the machine; the budget (<= 2.0) is tracked by
    // `ocean_sample bench`. This prints the number for the issue note.
    RecordProperty("floor_ratio", std::to_string(caustics / floor));
    auto alone = postfxtest::makeContext(postfx::Feature::Caustics);
    for (int i = 0; i < 20; ++i) {
      ASSERT_EQ(postfx::dispatch(*alone, frame), postfx::Result::Ok);
      glFinish();
    }
    std::printf("caustics alone %.3f ms\n",
                postfx::stats(*alone).pass(postfx::Pass::Caustics).medianMs);
  }
  glDeleteTextures(1, &water);
}

}  // namespace
