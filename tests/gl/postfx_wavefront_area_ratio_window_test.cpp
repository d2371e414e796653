// The WavefrontAreaRatio window as the caustics pass shows it: no texel grid where a pixel is
// smaller than a texel, no edge where the window ends (the tile irradiance continues it), and
// the GPU memory it takes is what the up-front estimate says.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/context.h"
#include "core/frame_geometry.h"
#include "core/frame_plan.h"
#include "core/gl_sizes.h"
#include "core/memory_estimate.h"
#include "core/shared_math.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "postfx_wavefront_area_ratio_util.h"

namespace {

using postfxtest::kPhysical;

class PostfxWavefrontAreaRatioWindowTest : public testsupport::GlTest {};

double upY(const postfx::FrameDesc& frame) {
  return -postfx::detail::refractedSunDown(frame.sun.direction, frame.water.ior).y;
}

// Mean |second difference| of a pixel row/column triplet, split by whether the triplet's two
// ends lie in different texel cells (a knot of the reconstruction between them: bilinear's slope
// jumps there) or in the same one.
struct Creases {
  double across = 0.0, within = 0.0;
  int acrossCount = 0, withinCount = 0;
  void add(double d2, bool crossesKnot) {
    if (crossesKnot) {
      across += std::abs(d2);
      ++acrossCount;
    } else {
      within += std::abs(d2);
      ++withinCount;
    }
  }
  double ratio() const {
    return (across / std::max(acrossCount, 1)) / std::max(within / std::max(withinCount, 1), 1e-12);
  }
};

// A floor 2 m under the camera, on the deepest layer, lit through a real sea, with texels of
// 25 cm (grid 64 over 16 m) seen at 2-3 m: a pixel covers 1/10 of a texel. The added light's
// second difference across the texel grid's knots (texel centres: bilinear creases there) must
// be no larger than inside the cells. The same measure on the texture read back and
// interpolated bilinearly proves it would see the blocks.
TEST_F(PostfxWavefrontAreaRatioWindowTest, NoTexelGridWhereAPixelIsUnderATexel) {
  auto ocean = postfxtest::makeSmallOcean(5.0);
  ASSERT_TRUE(ocean);
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(4.0, 160, 120));
  auto fx = postfxtest::makeContext(kPhysical);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
  postfxtest::useOcean(frame, *ocean);
  postfxtest::useWavefrontAreaRatio(frame, 64, 2,
                                    4.0f);  // layers at 1 and 4 m; the floor on the second
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const postfx::testing::CausticIrradianceInfo info = postfx::testing::causticIrradiance(*fx);
  const std::vector<float> texels = postfxtest::readIrradiance(info);
  const int w = scene.spec().width, h = scene.spec().height;
  const auto raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
  const double texel = info.windowSize / info.resolution, up = upY(frame);

  // Texel-centre coordinates (knots at integers) of each floor pixel well inside the window.
  std::vector<glm::dvec2> at(static_cast<size_t>(w) * h, glm::dvec2(-1.0));
  std::vector<double> bilinear(at.size(), 0.0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      if (t.hit != postfxtest::Hit::Floor) continue;
      const glm::dvec3 p = t.position + frame.camera.position;
      const glm::dvec2 c((p.x - info.windowOrigin.x) / texel - 0.5,
                         (p.z - info.windowOrigin.y) / texel - 0.5);
      const double n = info.resolution;
      if (std::min({c.x, c.y, n - c.x, n - c.y}) < 0.25 * n) continue;  // fade band and margin
      const size_t i = static_cast<size_t>(y) * w + x;
      at[i] = c;
      bilinear[i] = postfxtest::sampleLayer(info, texels, 1, p.x, p.z) * up;
    }
  Creases gpu, control;
  double footprint = 0.0;
  int steps = 0;
  for (int axis = 0; axis < 2; ++axis)
    for (int y = 1; y + 1 < h; ++y)
      for (int x = 1; x + 1 < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        const size_t d = axis == 0 ? 1 : static_cast<size_t>(w);
        const glm::dvec2 a = at[i - d], b = at[i], c = at[i + d];
        if (a.x < 0.0 || b.x < 0.0 || c.x < 0.0) continue;
        const bool knot = std::floor(a.x) != std::floor(c.x) || std::floor(a.y) != std::floor(c.y);
        gpu.add(static_cast<double>(raw[i - d]) - 2.0 * static_cast<double>(raw[i]) +
                    static_cast<double>(raw[i + d]),
                knot);
        control.add(bilinear[i - d] - 2.0 * bilinear[i] + bilinear[i + d], knot);
        footprint += glm::length(c - a) * 0.5;
        ++steps;
      }
  std::printf(
      "magnified (%.2f texel per pixel, %d triplets): second difference across / within texel "
      "cells %.2f (the same texels interpolated bilinearly: %.2f)\n",
      footprint / std::max(steps, 1), steps, gpu.ratio(), control.ratio());
  ASSERT_GT(gpu.acrossCount, 500);
  ASSERT_GT(gpu.withinCount, 500);
  EXPECT_LT(footprint / steps, 0.2) << "the pixels must be well under a texel";
  EXPECT_GT(control.ratio(), 3.0) << "the measure must see bilinear's creases";
  // A crease (a jump of the slope) makes the ratio grow as 1 / pixel step: 106 for bilinear
  // here. The B-spline's curvature is continuous but piecewise linear, largest at the knots:
  // measured 1.45.
  EXPECT_LT(gpu.ratio(), 2.0);
}

// Beyond the window the light is the tile irradiance's, exactly (the TileIrradiance model's
// frame gives the same pixels there); over the fade band the window's own irradiance (its
// texture read back) and the tile field have the same mean, so the band blends one light's two
// estimates, not two looks (the former ray-deviation continuation had half the mean: an edge).
// No light on the sky, NaN-free.
TEST_F(PostfxWavefrontAreaRatioWindowTest, ContinuesBeyondTheWindowWithoutAnEdge) {
  auto ocean = postfxtest::makeSmallOcean(5.0);
  ASSERT_TRUE(ocean);
  postfxtest::SceneSpec spec = postfxtest::wavefrontAreaRatioScene(4.0, 192, 128);
  spec.lookDirection = {0.0, -0.7, -1.0};  // the floor from 1 m to 20 m ahead
  postfxtest::Scene scene(spec);
  const int w = spec.width, h = spec.height;
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
  postfxtest::useOcean(frame, *ocean);
  postfxtest::useWavefrontAreaRatio(frame, 256, 2, 4.0f);  // the floor on the second layer
  frame.caustics.windowSize = 8.0f;                        // its edge 4 m from the camera
  // The window's continuation looks the tile field up at every pixel; so does this
  // TileIrradiance frame (by default its lookups run at half resolution).
  frame.caustics.tileLookupResolution = postfx::CausticsLookupResolution::Full;
  postfx::testing::CausticIrradianceInfo info;
  std::vector<float> texels;
  auto render = [&](postfx::CausticsModel model) {
    auto fx = postfxtest::makeContext(kPhysical);
    frame.caustics.model = model;
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    if (model == postfx::CausticsModel::WavefrontAreaRatio) {
      info = postfx::testing::causticIrradiance(*fx);
      texels = postfxtest::readIrradiance(info);
    }
    return postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
  };
  const auto physical = render(postfx::CausticsModel::WavefrontAreaRatio);
  const auto tile = render(postfx::CausticsModel::TileIrradiance);
  const auto former = render(postfx::CausticsModel::RayDeviation);  // the former continuation
  const double up = upY(frame);

  // The window's fade as the shader computes it: camera-centred, shrunk by the snap step.
  const double windowSize = 8.0, margin = double(1 << postfx::shared::IRRADIANCE_MIP_LEVELS) / 256;
  const double band = postfx::shared::IRRADIANCE_FADE_BAND;
  double worstOutside = 0.0;
  int outside = 0, inBand = 0;
  double sumPhysical = 0.0, sumWindow = 0.0, sumTile = 0.0, sumTile2 = 0.0, sumFormer = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      ASSERT_TRUE(std::isfinite(physical[i]) && physical[i] >= 0.0f) << physical[i];
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      if (t.hit != postfxtest::Hit::Floor) {
        EXPECT_EQ(physical[i], 0.0f);  // sky: no light
        continue;
      }
      const double u = t.position.x / windowSize + 0.5, v = t.position.z / windowSize + 0.5;
      const double edge = std::min({u, v, 1.0 - u, 1.0 - v}) - margin;
      const double p = physical[i], q = tile[i];
      if (edge < -0.01) {  // beyond the window (a pixel's slack)
        worstOutside = std::max(worstOutside, std::abs(p - q) / std::max(q, 0.1));
        ++outside;
      } else if (edge > 0.0 && edge < band) {
        sumPhysical += p;
        const glm::dvec3 world = t.position + frame.camera.position;
        sumWindow += postfxtest::sampleLayer(info, texels, 1, world.x, world.z) * up;
        sumTile += q;
        sumTile2 += q * q;
        sumFormer += static_cast<double>(former[i]);
        ++inBand;
      }
    }
  ASSERT_GT(outside, 1000);
  ASSERT_GT(inBand, 1000);
  const double meanPhysical = sumPhysical / inBand, meanTile = sumTile / inBand;
  const double meanWindow = sumWindow / inBand;
  const double spread = std::sqrt(std::max(sumTile2 / inBand - meanTile * meanTile, 0.0));
  std::printf(
      "window edge: %d pixels beyond it differ from the tile field by at most %.4f (relative); "
      "over the fade band (%d pixels) mean light: window %.4f, tile field %.4f (its pixel "
      "spread %.3f), blended %.4f; the former ray-deviation continuation %.4f\n",
      outside, worstOutside, inBand, meanWindow, meanTile, spread, meanPhysical,
      sumFormer / inBand);
  EXPECT_LT(worstOutside, 4e-3);  // R16F
  // The two fields over the band: no step larger than a tenth of the pattern's own
  // pixel-to-pixel spread, nor than 5 % of the mean; the blend between them.
  EXPECT_LT(std::abs(meanWindow - meanTile), 0.1 * spread);
  EXPECT_LT(std::abs(meanWindow - meanTile), 0.05 * meanTile);
  EXPECT_LE(meanPhysical, std::max(meanWindow, meanTile) * 1.01);
  EXPECT_GE(meanPhysical, std::min(meanWindow, meanTile) * 0.99);
}

// The estimate the frame is refused by (CreateDesc::memoryBudgetMiB) is, byte for byte, what the
// passes hold afterwards, asked of GL: the window's layers and mips, its grid points, the tile
// irradiance that continues it, and the raw output.
TEST_F(PostfxWavefrontAreaRatioWindowTest, MemoryEstimateIsWhatIsAllocated) {
  auto ocean = postfxtest::makeSmallOcean(5.0);
  ASSERT_TRUE(ocean);
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(4.0));
  auto fx = postfxtest::makeContext(kPhysical);
  const int w = scene.spec().width, h = scene.spec().height;
  for (const auto& [grid, layers] : {std::pair{64, 1}, std::pair{256, 4}, std::pair{96, 8}}) {
    SCOPED_TRACE("grid " + std::to_string(grid) + ", " + std::to_string(layers) + " layers");
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
    postfxtest::useOcean(frame, *ocean);
    postfxtest::useWavefrontAreaRatio(frame, grid, layers, 8.0f);
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    const postfx::detail::FramePlan plan = postfx::detail::planFrame(*fx, frame);
    EXPECT_TRUE(plan.wavefrontAreaRatio && plan.tile) << "the tile irradiance continues the window";
    const std::uint64_t estimate = postfx::detail::frameMemoryBytes(fx->desc, frame, w, h, plan);
    const std::uint64_t held =
        fx->wavefrontAreaRatio.allocatedBytes() + fx->tileIrradiance.allocatedBytes() +
        postfx::detail::textureBytes(postfx::testing::rawCausticTexture(*fx), 2);  // R16F
    std::printf("grid %d, %d layers: estimate %llu bytes, GL holds %llu (window %llu, tile %llu)\n",
                grid, layers, static_cast<unsigned long long>(estimate),
                static_cast<unsigned long long>(held),
                static_cast<unsigned long long>(fx->wavefrontAreaRatio.allocatedBytes()),
                static_cast<unsigned long long>(fx->tileIrradiance.allocatedBytes()));
    EXPECT_EQ(estimate, held);
  }
}

}  // namespace
