// Cascade skipping (CausticsSettings::minCascadeContrast, WaterSurface::rmsLaplacian and
// longestWavelength): a cascade a pixel cannot see must give exactly the image of a water
// texture without that cascade, and one it can see must still be sampled.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

class PostfxCascadeSkipTest : public testsupport::GlTest {};

constexpr double kLevel = -0.5;  // the floor is 7.5 m below it, the camera 1.5 m
constexpr int kCascades = 2;

// The test water texture with cascade 0 flattened on every mip level.
GLuint waterWithoutCascadeZero() {
  const GLuint water = postfxtest::makeWaterTexture(64, kCascades, 0.01);
  const float zero[4] = {0.0f, 0.0f, 0.0f, 1.0f};
  for (int level = 0, size = 64; size >= 1; ++level, size >>= 1)
    glClearTexSubImage(water, level, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT, zero);
  return water;
}

std::vector<float> rawCaustics(postfx::Context& fx, const postfxtest::Scene& scene,
                               const postfx::FrameDesc& frame) {
  scene.clearTarget(glm::vec4(0.0f));
  EXPECT_EQ(postfx::dispatch(fx, frame), postfx::Result::Ok) << postfx::lastError(&fx);
  return postfxtest::readRed(postfx::testing::rawCausticTexture(fx), scene.spec().width,
                             scene.spec().height);
}

double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, double(std::abs(a[i] - b[i])));
  return worst;
}

struct Images {
  std::vector<float> withoutCascadeZero, allCascades;
};

// The two references every case compares with: cascade 0 flattened, and every cascade sampled.
Images references(postfx::Context& fx, const postfxtest::Scene& scene, GLuint water,
                  GLuint flattened) {
  Images out;
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, flattened, kCascades, {}, kLevel);
  frame.caustics.minCascadeContrast = 0.0f;
  out.withoutCascadeZero = rawCaustics(fx, scene, frame);
  frame.water.texture.texture = water;
  out.allCascades = rawCaustics(fx, scene, frame);
  return out;
}

TEST_F(PostfxCascadeSkipTest, WavesThatCannotFocusAtTheReceiverDepthAreLeftOut) {
  postfxtest::Scene scene(postfxtest::SceneSpec{});
  const GLuint water = postfxtest::makeWaterTexture(64, kCascades, 0.01);
  const GLuint flattened = waterWithoutCascadeZero();
  auto fx = postfxtest::makeContext(postfxtest::kRaw);
  const Images ref = references(*fx, scene, water, flattened);
  const double cascadeZeroEffect = maxDifference(ref.withoutCascadeZero, ref.allCascades);
  ASSERT_GT(cascadeZeroEffect, 0.05) << "cascade 0 must matter for the test to mean anything";

  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, kCascades, {}, kLevel);
  frame.caustics.minCascadeContrast = 0.1f;
  // Gentle waves: modulation at <= 10 m of path ~ 10 * 0.25 * 1e-3 = 2.5e-3, far below 0.1.
  frame.water.rmsLaplacian[0] = 1e-3;
  const double skipped = maxDifference(rawCaustics(*fx, scene, frame), ref.withoutCascadeZero);
  // Steep curvature: modulation >= 1.5 * 0.25 * 10 ~ 4 at the shallowest receiver: full weight.
  frame.water.rmsLaplacian[0] = 10.0;
  const double kept = maxDifference(rawCaustics(*fx, scene, frame), ref.allCascades);
  std::printf(
      "cascade 0 changes the raw caustics by up to %.3f; skipped: %.2g from the image "
      "without it; kept: %.2g from the image with it\n",
      cascadeZeroEffect, skipped, kept);
  EXPECT_LT(skipped, 1e-6);
  EXPECT_LT(kept, 1e-6);
  glDeleteTextures(1, &water);
  glDeleteTextures(1, &flattened);
}

TEST_F(PostfxCascadeSkipTest, ContrastFadesInWithReceiverDepth) {
  // Cut-off 0.1 (fades in between modulations 0.1 and 0.2). The test floor sits 7.5 m below the
  // level, the second floor (x > 0) 17.5 m.
  postfxtest::SceneSpec spec;
  spec.sphere = false;
  spec.stepX = 0.0;
  spec.floorY2 = -18.0;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, kCascades, 0.01);
  const GLuint flattened = waterWithoutCascadeZero();
  auto fx = postfxtest::makeContext(postfxtest::kRaw);
  const Images ref = references(*fx, scene, water, flattened);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, kCascades, {}, kLevel);
  frame.caustics.minCascadeContrast = 0.1f;
  // gain = (1 - 1/n) * laplacian / cos(theta_t) = 0.0119 / 0.977 = 0.0122 per metre of depth
  // (this sun refracts to 12.4 degrees): 0.091 at 7.5 m (skipped), 0.213 at 17.5 m (full).
  frame.water.rmsLaplacian[0] = 0.0119 / (1.0 - 1.0 / 1.333);
  const std::vector<float> image = rawCaustics(*fx, scene, frame);
  double shallowSkipped = 0.0, deepKept = 0.0;
  int shallow = 0, deep = 0;
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      if (t.hit != postfxtest::Hit::Floor) continue;
      const size_t i = static_cast<size_t>(y * spec.width + x);
      const double depthBelow = kLevel - (spec.camera.y + t.position.y);
      if (depthBelow < 7.9) {
        shallowSkipped =
            std::max(shallowSkipped, double(std::abs(image[i] - ref.withoutCascadeZero[i])));
        ++shallow;
      } else if (depthBelow > 17.0) {
        deepKept = std::max(deepKept, double(std::abs(image[i] - ref.allCascades[i])));
        ++deep;
      }
    }
  }
  std::printf("shallow floor (%d px) vs no cascade 0: %.2g; deep floor (%d px) vs all: %.2g\n",
              shallow, shallowSkipped, deep, deepKept);
  ASSERT_GT(shallow, 100);
  ASSERT_GT(deep, 100);
  EXPECT_LT(shallowSkipped, 1e-6);
  EXPECT_LT(deepKept, 1e-6);
  glDeleteTextures(1, &water);
  glDeleteTextures(1, &flattened);
}

TEST_F(PostfxCascadeSkipTest, WavesFinerThanTheFootprintAreLeftOut) {
  postfxtest::Scene scene(postfxtest::SceneSpec{});
  const GLuint water = postfxtest::makeWaterTexture(64, kCascades, 0.01);
  const GLuint flattened = waterWithoutCascadeZero();
  auto fx = postfxtest::makeContext(postfxtest::kRaw);
  const Images ref = references(*fx, scene, water, flattened);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, kCascades, {}, kLevel);
  // 1 mm waves: every pixel's footprint (>= 1 cm here) is wider than half of them.
  frame.water.longestWavelength[0] = 1e-3;
  const double skipped = maxDifference(rawCaustics(*fx, scene, frame), ref.withoutCascadeZero);
  frame.water.longestWavelength[0] = 1e3;
  const double kept = maxDifference(rawCaustics(*fx, scene, frame), ref.allCascades);
  std::printf("footprint rule: skipped %.2g, kept %.2g\n", skipped, kept);
  EXPECT_LT(skipped, 1e-6);
  EXPECT_LT(kept, 1e-6);
  glDeleteTextures(1, &water);
  glDeleteTextures(1, &flattened);
}

TEST_F(PostfxCascadeSkipTest, BadCascadeStatisticsAreRefused) {
  postfxtest::Scene scene(postfxtest::SceneSpec{});
  const GLuint water = postfxtest::makeWaterTexture(16, kCascades, 0.01);
  auto fx = postfxtest::makeContext(postfxtest::kRaw);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto expectRefused = [&](auto&& edit, const char* field) {
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, kCascades, {}, kLevel);
    edit(frame);
    scene.clearTarget(glm::vec4(0.25f));
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument) << field;
    EXPECT_NE(std::string(postfx::lastError(fx.get())).find(field), std::string::npos)
        << postfx::lastError(fx.get());
    for (const glm::vec4& p : postfxtest::readRgba(scene.target, 128, 72))
      ASSERT_EQ(p, glm::vec4(0.25f)) << "nothing may be drawn";
  };
  expectRefused([&](postfx::FrameDesc& f) { f.water.rmsLaplacian[1] = double(nan); },
                "rmsLaplacian");
  expectRefused([](postfx::FrameDesc& f) { f.water.longestWavelength[0] = -1.0; },
                "longestWavelength");
  expectRefused([](postfx::FrameDesc& f) { f.caustics.minCascadeContrast = 1.5f; },
                "minCascadeContrast");
  expectRefused([&](postfx::FrameDesc& f) { f.caustics.minCascadeContrast = nan; },
                "minCascadeContrast");
  glDeleteTextures(1, &water);
}

}  // namespace
