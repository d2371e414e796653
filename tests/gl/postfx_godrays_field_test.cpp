// God rays from the caustics' own light field (the TileIrradiance model, the default): the
// shafts line up with the seabed pattern below them (far better than ray deviation's slope factor),
// flat water gives exactly the unmodulated shafts, the field's pre-pass runs for god rays alone
// and is left out when nothing reads it, and the contracts hold (no light above the water or on
// the sky, finite, bounded by the field's clamp).
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfx::Feature;
using postfx::Result;
using postfxtest::Hit;

class PostfxGodRaysFieldTest : public testsupport::GlTest {};

constexpr glm::dvec3 kSun{0.3, 1.0, 0.2};

// Dispatches `frame` into a cleared target and returns the light added.
std::vector<glm::vec4> render(postfx::Context& fx, const postfxtest::Scene& scene,
                              const postfx::FrameDesc& frame) {
  scene.clearTarget(glm::vec4(0.0f));
  EXPECT_EQ(postfx::dispatch(fx, frame), Result::Ok) << postfx::lastError(&fx);
  return postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height);
}

// Pearson correlation of the green channels of `a` and `b` over the pixels in `use`.
double correlation(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b,
                   const std::vector<bool>& use) {
  double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0, n = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (!use[i]) continue;
    const double x = a[i].g, y = b[i].g;
    sa += x;
    sb += y;
    saa += x * x;
    sbb += y * y;
    sab += x * y;
    n += 1;
  }
  const double cov = sab / n - sa / n * sb / n;
  const double va = saa / n - sa / n * sa / n, vb = sbb / n - sb / n * sb / n;
  return cov / std::sqrt(std::max(va * vb, 1e-300));
}

postfx::FrameDesc fieldFrame(const postfxtest::Scene& scene, GLuint water,
                             postfx::CausticsModel model) {
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  frame.sun.direction = glm::normalize(kSun);
  frame.caustics.model = model;
  frame.godRays.resolution = postfx::GodRayResolution::Full;
  frame.godRays.sampleCount = 64;
  return frame;
}

// Looking down along the refracted sun from `height` above a flat seabed 8 m deep: every view
// ray follows one flat-water light ray, so its shaft is the light that lands on the seabed pixel
// it ends on, integrated over the `height` above it. Returns the correlation of the shafts with
// the seabed caustics (tile model) below them, the god rays reading the tile field (withField)
// or ray deviation's factor (withSlopes).
void shaftSeabedCorrelation(double height, double& withField, double& withSlopes,
                            postfx::CausticsModel model = postfx::CausticsModel::TileIrradiance) {
  postfxtest::SceneSpec spec;
  spec.width = 96;
  spec.height = 96;
  spec.sphere = false;
  spec.floorY = -8.0;
  spec.camera = {0.0, spec.floorY + height, 0.0};
  spec.lookDirection = postfx::detail::refractedSunDown(glm::normalize(kSun), 1.333);
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  const Feature physical = model == postfx::CausticsModel::WavefrontAreaRatio
                               ? Feature::WavefrontAreaRatio
                               : Feature::None;
  auto caustics = postfxtest::makeContext(Feature::Caustics | physical);
  auto godRays = postfxtest::makeContext(Feature::GodRays | physical);
  ASSERT_EQ(postfx::testing::setGodRaySampling(*godRays,
                                               postfx::testing::GodRaySampling::UniformAlongRay),
            Result::Ok);
  postfx::FrameDesc frame = fieldFrame(scene, water, model);
  ASSERT_NEAR(frame.water.ior, 1.333f, 1e-6f) << "the view follows the refracted sun";
  frame.godRays.enabled = false;
  const std::vector<glm::vec4> seabed = render(*caustics, scene, frame);
  frame.godRays.enabled = true;
  frame.caustics.enabled = false;
  const std::vector<glm::vec4> field = render(*godRays, scene, frame);
  frame.caustics.model = postfx::CausticsModel::RayDeviation;
  const std::vector<glm::vec4> slopes = render(*godRays, scene, frame);
  std::vector<bool> floor(seabed.size());
  for (size_t i = 0; i < floor.size(); ++i)
    floor[i] = scene.truth(int(i) % spec.width, int(i) / spec.width).hit == Hit::Floor;
  withField = correlation(field, seabed, floor);
  withSlopes = correlation(slopes, seabed, floor);
  std::printf(
      "god rays over %.1f m vs the seabed caustics below (correlation, %s model): its field "
      "%.3f, ray deviation %.3f\n",
      height, physical == Feature::None ? "tile" : "physical", withField, withSlopes);
  glDeleteTextures(1, &water);
}

// Seed 002's factor depends on the slopes where the light entered, not on how far it has
// travelled since: it cannot show where the light focuses. The tile field is the seabed's own
// light at every depth. Measured (96 x 96, 64 uniform samples): 0.5 m above the seabed (the
// in-water source just above it) correlation 0.84 against -0.11 for ray deviation; over 3 m, where
// the shaft averages the pattern over its changing focus, 0.44 against 0.21.
TEST_F(PostfxGodRaysFieldTest, ShaftsLineUpWithTheSeabedPattern) {
  double field = 0.0, slopes = 0.0;
  shaftSeabedCorrelation(0.5, field, slopes);
  RecordProperty("correlation_field_0_5m", std::to_string(field));
  RecordProperty("correlation_seed002_0_5m", std::to_string(slopes));
  EXPECT_GT(field, 0.75);
  EXPECT_GT(field, slopes + 0.5);
  shaftSeabedCorrelation(3.0, field, slopes);
  RecordProperty("correlation_field_3m", std::to_string(field));
  RecordProperty("correlation_seed002_3m", std::to_string(slopes));
  EXPECT_GT(field, slopes + 0.15);
}

// The same with the physical (window) model, whose field the god rays read inside its window.
TEST_F(PostfxGodRaysFieldTest, PhysicalShaftsLineUpWithTheSeabedPattern) {
  double field = 0.0, slopes = 0.0;
  shaftSeabedCorrelation(0.5, field, slopes, postfx::CausticsModel::WavefrontAreaRatio);
  EXPECT_GT(field, 0.75);
  EXPECT_GT(field, slopes + 0.5);
}

// Beyond the physical window the seabed is lit by the tile field, and so are the shafts: with a
// window of 1 m around the camera nearly every sample lies beyond it, and the physical model's
// shafts are the tile model's (they were ray deviation's factor, which does not match that seabed).
TEST_F(PostfxGodRaysFieldTest, PhysicalShaftsBeyondTheWindowAreTheTileFields) {
  postfxtest::SceneSpec spec;
  spec.width = 96;
  spec.height = 54;
  spec.sphere = false;
  spec.lookDirection = {0.0, -0.3, -1.0};
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  auto fx =
      postfxtest::makeContext(Feature::Caustics | Feature::GodRays | Feature::WavefrontAreaRatio);
  postfx::FrameDesc frame = fieldFrame(scene, water, postfx::CausticsModel::TileIrradiance);
  frame.caustics.enabled = false;
  frame.godRays.sampleCount = 16;
  frame.caustics.windowSize = 1.0f;
  const std::vector<glm::vec4> tile = render(*fx, scene, frame);
  frame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  const std::vector<glm::vec4> physical = render(*fx, scene, frame);
  frame.caustics.model = postfx::CausticsModel::RayDeviation;
  const std::vector<glm::vec4> seed002 = render(*fx, scene, frame);
  double level = 0.0, fromTile = 0.0, seed002FromTile = 0.0;
  for (size_t i = 0; i < tile.size(); ++i) {
    level += double(tile[i].g);
    fromTile += std::abs(double(physical[i].g) - double(tile[i].g));
    seed002FromTile += std::abs(double(seed002[i].g) - double(tile[i].g));
  }
  ASSERT_GT(level, 1e-3 * double(tile.size())) << "the test must see god rays";
  std::printf(
      "physical model's shafts, 1 m window: mean |difference| from the tile model's %.4f "
      "of its light (ray deviation's %.4f)\n",
      fromTile / level, seed002FromTile / level);
  RecordProperty("physical_vs_tile", std::to_string(fromTile / level));
  RecordProperty("seed002_vs_tile", std::to_string(seed002FromTile / level));
  EXPECT_LT(fromTile / level, 0.02);
  EXPECT_GT(seed002FromTile / level, 5.0 * fromTile / level);
  glDeleteTextures(1, &water);
}

// Flat water: the field is 1 everywhere, as ray deviation's factor is, so both give the same
// shafts.
TEST_F(PostfxGodRaysFieldTest, FlatWaterGivesTheUnmodulatedShafts) {
  postfxtest::SceneSpec spec;
  spec.width = 64;
  spec.height = 36;
  spec.lookDirection = {0.0, -0.25, -1.0};
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.0);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  for (postfx::GodRayResolution resolution :
       {postfx::GodRayResolution::Full, postfx::GodRayResolution::Half}) {
    postfx::FrameDesc frame = fieldFrame(scene, water, postfx::CausticsModel::TileIrradiance);
    frame.godRays.sampleCount = 16;
    frame.godRays.resolution = resolution;
    const std::vector<glm::vec4> field = render(*fx, scene, frame);
    frame.caustics.model = postfx::CausticsModel::RayDeviation;
    const std::vector<glm::vec4> unmodulated = render(*fx, scene, frame);
    double peak = 0.0;
    for (size_t i = 0; i < field.size(); ++i) {
      peak = std::max(peak, double(unmodulated[i].g));
      for (int c = 0; c < 3; ++c)
        // RGBA16F irradiance: ~11 bits.
        ASSERT_NEAR(field[i][c], unmodulated[i][c], 2e-3f * unmodulated[i][c] + 1e-7f)
            << "pixel " << i << " channel " << c;
    }
    EXPECT_GT(peak, 1e-3) << "the test must see god rays";
  }
  glDeleteTextures(1, &water);
}

// The field's pre-pass runs for god rays alone (caustics disabled) and not when neither draws.
TEST_F(PostfxGodRaysFieldTest, FieldComputedForGodRaysAloneAndLeftOutWithoutThem) {
  postfxtest::SceneSpec spec;
  spec.width = 32;
  spec.height = 18;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::Caustics | Feature::GodRays);
  postfx::FrameDesc frame = fieldFrame(scene, water, postfx::CausticsModel::TileIrradiance);
  frame.caustics.enabled = false;
  const postfx::PassStats& tile = postfx::stats(*fx).pass(postfx::Pass::TileIrradiance);
  const postfx::PassStats& caustics = postfx::stats(*fx).pass(postfx::Pass::Caustics);
  for (int i = 0; i < postfx::kTimerRingDepth + 1; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    glFinish();
  }
  EXPECT_FALSE(tile.skipped) << "the god rays read the field";
  EXPECT_GT(tile.lastMs, 0.0);
  EXPECT_TRUE(caustics.skipped);
  frame.godRays.enabled = false;
  for (int i = 0; i < postfx::kTimerRingDepth + 1; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    glFinish();
  }
  EXPECT_TRUE(tile.skipped) << "nothing reads the field";
  EXPECT_EQ(tile.lastMs, 0.0);
  // The physical model's pre-pass likewise.
  auto physical =
      postfxtest::makeContext(Feature::Caustics | Feature::GodRays | Feature::WavefrontAreaRatio);
  frame.godRays.enabled = true;
  frame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  for (int i = 0; i < postfx::kTimerRingDepth + 1; ++i) {
    ASSERT_EQ(postfx::dispatch(*physical, frame), Result::Ok) << postfx::lastError(physical.get());
    glFinish();
  }
  EXPECT_FALSE(postfx::stats(*physical).pass(postfx::Pass::WavefrontAreaRatio).skipped);
  // The tile field continues the seabed's window beyond its edge, so it runs too.
  EXPECT_FALSE(postfx::stats(*physical).pass(postfx::Pass::TileIrradiance).skipped);
  // A context with god rays and no caustics has the tile pre-pass too.
  auto godRaysOnly = postfxtest::makeContext(Feature::GodRays);
  EXPECT_TRUE(postfx::stats(*godRaysOnly).pass(postfx::Pass::TileIrradiance).present);
  glDeleteTextures(1, &water);
}

// Camera above the water: sky rays and everything above the level get no light; every value is
// finite, non-negative and within E * intensity * sigma_s / sigma_t times the field's clamp
// (the field's spatial mean is flat water's 1, but a ray inside a focused sheet sees more).
TEST_F(PostfxGodRaysFieldTest, NoLightAboveWaterOrOnSkyFiniteAndBounded) {
  postfxtest::SceneSpec spec;
  spec.width = 64;
  spec.height = 36;
  spec.lookDirection = {0.0, -0.15, -1.0};
  spec.sphereCenter = {2.0, 0.0, -8.0};
  postfxtest::Scene scene(spec);
  const double level = -3.0;  // 1 m below the camera
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  for (postfx::GodRayResolution resolution :
       {postfx::GodRayResolution::Full, postfx::GodRayResolution::Quarter}) {
    postfx::FrameDesc frame = fieldFrame(scene, water, postfx::CausticsModel::TileIrradiance);
    frame.water.level = level;
    frame.godRays.resolution = resolution;
    frame.godRays.sampleCount = 16;
    const std::vector<glm::vec4> image = render(*fx, scene, frame);
    const glm::vec3 sigmaT = frame.water.absorption + frame.water.scattering;
    const float clamp = std::min(frame.caustics.maxIrradiance, postfx::shared::TILE_MAX_IRRADIANCE);
    const double levelRel = level - spec.camera.y;
    int lit = 0;
    for (int y = 0; y < spec.height; ++y) {
      for (int x = 0; x < spec.width; ++x) {
        const glm::vec4 p = image[static_cast<size_t>(y * spec.width + x)];
        const postfxtest::PixelTruth& t = scene.truth(x, y);
        for (int c = 0; c < 3; ++c) {
          ASSERT_TRUE(std::isfinite(p[c]) && p[c] >= 0.0f) << x << "," << y;
          const float bound = frame.sun.irradiance[c] * frame.godRays.intensity *
                              frame.water.scattering[c] / sigmaT[c] * clamp;
          ASSERT_LE(p[c], bound * 1.001f) << x << "," << y;
        }
        // Full resolution only: a reduced texel's upsample may borrow a neighbour's light.
        if (resolution != postfx::GodRayResolution::Full) continue;
        if (t.hit == Hit::Sky || t.position.y > levelRel + 1e-3) {
          EXPECT_EQ(p.r + p.g + p.b, 0.0f) << x << "," << y << " (sky or above the water)";
        } else if (p.g > 0.0f) {
          ++lit;
        }
      }
    }
    if (resolution == postfx::GodRayResolution::Full) {
      EXPECT_GT(lit, spec.width * spec.height / 10);
    }
  }
  glDeleteTextures(1, &water);
}

// The dense march's test hook: phases outside [0, 1) are refused with a message naming the hook,
// and the mean of frames at evenly spread phases refines the march (here 4 x 16 samples against
// 64: the same sample points, each frame normalised by its own transmittance weights).
TEST_F(PostfxGodRaysFieldTest, UniformPhasesAverageToTheFinerMarch) {
  postfxtest::SceneSpec spec;
  spec.width = 48;
  spec.height = 27;
  spec.lookDirection = {0.0, -0.25, -1.0};
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  for (float bad : {-0.1f, 1.0f, std::numeric_limits<float>::quiet_NaN()}) {
    EXPECT_EQ(postfx::testing::setGodRayUniformPhase(*fx, bad), Result::InvalidArgument);
    EXPECT_NE(std::string(postfx::lastError(fx.get())).find("setGodRayUniformPhase"),
              std::string::npos);
  }
  ASSERT_EQ(
      postfx::testing::setGodRaySampling(*fx, postfx::testing::GodRaySampling::UniformAlongRay),
      Result::Ok);
  postfx::FrameDesc frame = fieldFrame(scene, water, postfx::CausticsModel::TileIrradiance);
  frame.godRays.sampleCount = 64;
  ASSERT_EQ(postfx::testing::setGodRayUniformPhase(*fx, 0.5f), Result::Ok);
  const std::vector<glm::vec4> fine = render(*fx, scene, frame);
  frame.godRays.sampleCount = 16;
  std::vector<glm::dvec3> mean(fine.size(), glm::dvec3(0.0));
  for (int k = 0; k < 4; ++k) {
    // Sample i of phase k sits at step (4 i + k + 0.5) / 64 of the ray: the 64-sample march's.
    ASSERT_EQ(postfx::testing::setGodRayUniformPhase(*fx, (float(k) + 0.5f) / 4.0f), Result::Ok);
    const std::vector<glm::vec4> image = render(*fx, scene, frame);
    for (size_t i = 0; i < image.size(); ++i) mean[i] += glm::dvec3(image[i]) / 4.0;
  }
  // One 16-sample frame at the middle phase, for scale.
  ASSERT_EQ(postfx::testing::setGodRayUniformPhase(*fx, 0.5f), Result::Ok);
  const std::vector<glm::vec4> coarse = render(*fx, scene, frame);
  double peak = 0.0, meanError = 0.0, coarseError = 0.0, norm = 0.0;
  for (size_t i = 0; i < fine.size(); ++i) {
    const double f = fine[i].g;
    peak = std::max(peak, f);
    meanError += (mean[i].g - f) * (mean[i].g - f);
    coarseError += (double(coarse[i].g) - f) * (double(coarse[i].g) - f);
    norm += f * f;
  }
  std::printf(
      "4 phases x 16 samples vs 64 samples: relative RMSE %.4f (one 16-sample frame %.4f)\n",
      std::sqrt(meanError / norm), std::sqrt(coarseError / norm));
  EXPECT_LT(meanError, 0.25 * coarseError) << "the phases must refine the march";
  EXPECT_LT(std::sqrt(meanError / norm), 0.05);
  EXPECT_GT(peak, 1e-3);
  glDeleteTextures(1, &water);
}

}  // namespace
