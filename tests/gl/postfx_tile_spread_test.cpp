// The TileIrradiance field's spread (CausticsSettings::tileUnresolvedSpread, Sun's disc): a
// convolution, so it keeps the flux and only lowers the contrast; more of it (a wider disc, a
// deeper floor) lowers it more; it reads nothing the water does not hold (a texture no finer
// than the points has no unresolved slopes, so with a point sun it changes nothing); and a sun
// disc outside its range is refused with the target untouched.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfxtest::Hit;
using postfxtest::kRaw;

class PostfxTileSpreadTest : public testsupport::GlTest {};

struct FloorStats {
  double mean = 0.0, std = 0.0;
  int pixels = 0;
};

// The raw caustic light over the floor pixels lit from above, on a floor looking straight down.
FloorStats floorStats(const postfxtest::Scene& scene, const std::vector<float>& raw) {
  const int w = scene.spec().width, h = scene.spec().height;
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (scene.truth(x, y).hit != Hit::Floor) continue;
      const double v = raw[static_cast<size_t>(y * w + x)];
      sum += v;
      sum2 += v * v;
      ++n;
    }
  }
  FloorStats s;
  s.pixels = n;
  if (n == 0) return s;
  s.mean = sum / n;
  s.std = std::sqrt(std::max(sum2 / n - s.mean * s.mean, 0.0));
  return s;
}

struct Run {
  bool unresolved = false;
  float discDegrees = 0.0f;
};

class SpreadScene {
 public:
  SpreadScene(int waterTexels, double floorY) {
    spec_.sphere = false;
    spec_.width = 160;
    spec_.height = 90;
    spec_.camera = {0.0, -1.0, 0.0};
    spec_.lookDirection = {0.0, -1.0, -1e-3};  // straight down: a floor patch wider than a tile
    spec_.floorY = floorY;
    scene_ = std::make_unique<postfxtest::Scene>(spec_);
    water_ = postfxtest::makeWaterTexture(waterTexels, 2, 0.01);
    fx_ = postfxtest::makeContext(kRaw);
  }
  ~SpreadScene() { glDeleteTextures(1, &water_); }

  postfx::FrameDesc frame(const Run& run) const {
    postfx::FrameDesc frame = postfxtest::makeFrame(*scene_, water_, 2);
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    frame.caustics.tileUnresolvedSpread = run.unresolved;
    frame.caustics.tileMinModulation = 0.0f;  // keep every cascade: the test compares fields
    frame.sun.angularDiameterDegrees = run.discDegrees;
    // Short tiles: the pattern is a few centimetres fine, what the disc's blur is at depth.
    frame.water.tileSize[0] = 2.5;
    frame.water.tileSize[1] = 1.25;
    return frame;
  }

  std::vector<float> raw(const Run& run) {
    const postfx::Result r = postfx::dispatch(*fx_, frame(run));
    EXPECT_EQ(r, postfx::Result::Ok) << postfx::lastError(fx_.get());
    return postfxtest::readRed(postfx::testing::rawCausticTexture(*fx_), spec_.width, spec_.height);
  }

  FloorStats stats(const Run& run) { return floorStats(*scene_, raw(run)); }
  postfx::Context& context() { return *fx_; }
  const postfxtest::Scene& scene() const { return *scene_; }

 private:
  postfxtest::SceneSpec spec_;
  std::unique_ptr<postfxtest::Scene> scene_;
  GLuint water_ = 0;
  postfxtest::ContextPtr fx_;
};

TEST_F(PostfxTileSpreadTest, KeepsTheFluxAndLowersTheContrastTheWiderTheDisc) {
  SpreadScene s(256, -12.0);
  const FloorStats sharp = s.stats({false, 0.0f});
  ASSERT_GT(sharp.pixels, 10000);
  ASSERT_GT(sharp.std, 0.05 * sharp.mean) << "the test needs a pattern to soften";
  double previousStd = sharp.std;
  for (float disc : {0.53f, 2.0f, 6.0f}) {
    const FloorStats soft = s.stats({false, disc});
    std::printf("disc %.2f deg: mean %.4f (point sun %.4f), std %.4f (%.4f)\n", double(disc),
                soft.mean, sharp.mean, soft.std, sharp.std);
    // A convolution of a periodic field keeps its mean; the floor samples many periods.
    EXPECT_NEAR(soft.mean / sharp.mean, 1.0, 0.02) << disc;
    EXPECT_LT(soft.std, previousStd) << disc;
    previousStd = soft.std;
  }
  const FloorStats unresolved = s.stats({true, 0.0f});
  EXPECT_NEAR(unresolved.mean / sharp.mean, 1.0, 0.02);
  EXPECT_LT(unresolved.std, sharp.std) << "a 256-texel sea has slopes inside the points' cells";
}

TEST_F(PostfxTileSpreadTest, DeeperFloorsSoftenMore) {
  // The disc's blur grows with depth: its share of the contrast lost grows too.
  double lostShallow = 0.0, lostDeep = 0.0;
  for (double floorY : {-3.0, -24.0}) {
    SpreadScene s(256, floorY);
    const FloorStats sharp = s.stats({false, 0.0f});
    const FloorStats soft = s.stats({false, 2.0f});
    (floorY > -10.0 ? lostShallow : lostDeep) = 1.0 - soft.std / sharp.std;
  }
  std::printf("contrast lost to a 2 deg disc: %.3f at 3 m, %.3f at 24 m\n", lostShallow, lostDeep);
  EXPECT_GT(lostDeep, lostShallow + 0.05);
}

TEST_F(PostfxTileSpreadTest, WaterNoFinerThanThePointsHasNothingToSpread) {
  // 32 texels a tile side: every point cell holds at most one texel, so no slope goes unresolved.
  SpreadScene s(32, -8.0);
  const std::vector<float> off = s.raw({false, 0.0f});
  const std::vector<float> on = s.raw({true, 0.0f});
  ASSERT_EQ(off.size(), on.size());
  double maxDiff = 0.0;
  for (size_t i = 0; i < off.size(); ++i)
    maxDiff = std::max(maxDiff, std::abs(double(off[i]) - double(on[i])));
  EXPECT_LT(maxDiff, 2e-3) << "R16F: ~11 bits";
}

// Plane waves along x and z with `periods` whole periods per tile and slope amplitude `slope`.
GLuint makeRipples(int size, int periods, double slope) {
  std::vector<glm::vec4> texels(static_cast<size_t>(size * size));
  const double twoPi = 6.283185307179586;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double px = twoPi * periods * (x + 0.5) / size;
      const double pz = twoPi * (periods + 1) * (y + 0.5) / size;
      texels[static_cast<size_t>(y * size + x)] =
          glm::vec4(float(slope * std::cos(px)), float(slope * std::cos(pz)), 0.0f, 1.0f);
    }
  }
  return postfxtest::makeWaterTextureFromTexels(size, texels);
}

// Ripples far shorter than a point's cell, 8 m down (dozens of their focal lengths), scatter
// the light as a diffuser does: it arrives near-uniform, as traced light through them does.
// The points must read their cell's mean (the mip level), not alias the ripples into a pattern
// of their own; the same waves long enough for the points to resolve do make one.
TEST_F(PostfxTileSpreadTest, RipplesFinerThanThePointsGiveNearUniformLightAtDepth) {
  auto contrast = [](int periods) {
    postfxtest::SceneSpec spec;
    spec.sphere = false;
    spec.width = 160;
    spec.height = 90;
    spec.camera = {0.0, -1.0, 0.0};
    spec.lookDirection = {0.0, -1.0, -1e-3};
    spec.floorY = -8.0;
    postfxtest::Scene scene(spec);
    const GLuint water = makeRipples(256, periods, 0.1);
    postfxtest::ContextPtr fx = postfxtest::makeContext(kRaw);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1);
    frame.water.tileSize[0] = 2.5;  // 256 texels of 1 cm; 32 points of 8 cm
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    frame.caustics.tileResolution = 32;
    frame.caustics.tileMinModulation = 0.0f;
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    const FloorStats stats = floorStats(
        scene,
        postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height));
    glDeleteTextures(1, &water);
    EXPECT_GT(stats.pixels, 10000);
    return stats;
  };
  const FloorStats ripples = contrast(100);  // 2.5 cm waves: a third of a point's cell
  const FloorStats waves = contrast(3);      // 83 cm waves: 10 points each
  std::printf(
      "8 m under ripples: mean %.4f, contrast %.4f; under resolved waves: mean %.4f, "
      "contrast %.4f\n",
      ripples.mean, ripples.std / ripples.mean, waves.mean, waves.std / waves.mean);
  EXPECT_LT(ripples.std / ripples.mean, 0.03);
  EXPECT_GT(waves.std / waves.mean, 0.2) << "the test needs waves the points resolve";
  // Flat water's raw light is n.l of the floor facing the refracted sun; the ripples keep it.
  EXPECT_NEAR(ripples.mean / waves.mean, 1.0, 0.03);
}

TEST_F(PostfxTileSpreadTest, SunDiscOutsideItsRangeIsRefusedAndChangesNothing) {
  SpreadScene s(64, -8.0);
  const postfxtest::Scene& scene = s.scene();
  const glm::vec4 marker(0.125f, 0.25f, 0.5f, 1.0f);
  for (float disc : {-0.1f, 10.5f, std::nanf(""), INFINITY}) {
    scene.clearTarget(marker);
    const std::vector<glm::vec4> before =
        postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height);
    postfx::FrameDesc frame = s.frame({true, 0.0f});
    frame.sun.angularDiameterDegrees = disc;
    EXPECT_EQ(postfx::dispatch(s.context(), frame), postfx::Result::InvalidArgument) << disc;
    EXPECT_NE(std::string(postfx::lastError(&s.context())).find("angularDiameterDegrees"),
              std::string::npos)
        << postfx::lastError(&s.context());
    const std::vector<glm::vec4> after =
        postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height);
    EXPECT_EQ(std::memcmp(before.data(), after.data(), before.size() * sizeof(before[0])), 0);
  }
}

}  // namespace
