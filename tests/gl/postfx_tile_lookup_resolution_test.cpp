// CausticsSettings::tileLookupResolution: the TileIrradiance lookups at half resolution (the
// default) against every pixel's own lookup. The reduced lookups are filtered over 2 x 2 pixels
// and blended back by distance similarity, so they must give the same light as the full ones up
// to that filtering, exactly the unperturbed light under flat water, nothing where the full ones
// give nothing, and no light carried from the far floor onto a nearer surface's edge.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "core/frame_geometry.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfx::CausticsLookupResolution;
using postfxtest::Hit;
using postfxtest::kRaw;

class PostfxTileLookupResolutionTest : public testsupport::GlTest {};

// The raw caustic factor of one frame with the lookups at `lookup`.
std::vector<float> rawFactor(const postfxtest::Scene& scene, const postfxtest::SceneSpec& spec,
                             GLuint water, int cascades, CausticsLookupResolution lookup) {
  auto fx = postfxtest::makeContext(kRaw);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, cascades, {}, 0.0);
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  frame.caustics.tileLookupResolution = lookup;
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  return postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0.0, mb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ma += a[i] / n;
    mb += b[i] / n;
  }
  double ab = 0.0, aa = 0.0, bb = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    ab += (a[i] - ma) * (b[i] - mb);
    aa += (a[i] - ma) * (a[i] - ma);
    bb += (b[i] - mb) * (b[i] - mb);
  }
  return ab / std::sqrt(std::max(aa * bb, 1e-300));
}

TEST_F(PostfxTileLookupResolutionTest, HalfGivesTheFullLookupsLightUpToItsFootprint) {
  postfxtest::SceneSpec spec;
  spec.width = 160;
  spec.height = 96;
  spec.lookDirection = {0.0, -1.0, -0.4};
  spec.sphere = false;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  const auto full = rawFactor(scene, spec, water, 3, CausticsLookupResolution::Full);
  const auto half = rawFactor(scene, spec, water, 3, CausticsLookupResolution::Half);
  std::vector<double> a, b;
  for (size_t i = 0; i < full.size(); ++i) {
    ASSERT_TRUE(std::isfinite(half[i])) << i;
    if (full[i] > 0.0f) {
      a.push_back(full[i]);
      b.push_back(half[i]);
    } else {
      EXPECT_EQ(half[i], 0.0f) << "pixel " << i << ": light where the full lookups give none";
    }
  }
  ASSERT_GT(a.size(), full.size() / 2);
  double meanFull = 0.0, meanHalf = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    meanFull += a[i];
    meanHalf += b[i];
  }
  const double r = correlation(a, b);
  std::printf("half vs full lookups: correlation %.4f, mean ratio %.4f over %zu pixels\n", r,
              meanHalf / meanFull, a.size());
  // Irradiance is linear: filtering it over twice the footprint keeps its mean. Measured: mean
  // ratio 1.0026, correlation 0.882 (this synthetic sea has detail down to the pixel).
  EXPECT_NEAR(meanHalf / meanFull, 1.0, 0.01);
  EXPECT_GT(r, 0.85);
  glDeleteTextures(1, &water);
}

// Sphere pixels next to the floor behind them: the half-resolution texels around such a pixel
// mix sphere and floor points, whose irradiance is unrelated. Weighted by distance, the
// sphere's edge keeps its own, compared as irradiance (the raw factor over N.L, which the
// upsample does not touch).
TEST_F(PostfxTileLookupResolutionTest, NoLightBleedsAcrossASilhouette) {
  postfxtest::SceneSpec spec;
  spec.width = 160;
  spec.height = 96;
  // A sphere 1.5-3.5 m deep over a floor 15 m deep: different stages of focus.
  spec.camera = {0.0, -1.0, 0.0};
  spec.lookDirection = {0.0, -0.6, -1.0};
  spec.sphereCenter = {0.0, -1.5, -5.0};
  spec.sphereRadius = 1.0;
  spec.floorY = -14.0;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  const auto full = rawFactor(scene, spec, water, 3, CausticsLookupResolution::Full);
  const auto half = rawFactor(scene, spec, water, 3, CausticsLookupResolution::Half);
  const postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, 0.0);
  const glm::dvec3 up = -postfx::detail::refractedSunDown(frame.sun.direction, frame.water.ior);
  const int w = spec.width, h = spec.height;
  // Irradiance where the surface faces the light well enough to divide by N.L (1 m below the
  // level, the surface fade is 1 everywhere here).
  auto irradiance = [&](const std::vector<float>& raw, int x, int y) {
    const double nDotL = glm::dot(scene.truth(x, y).normal, up);
    return nDotL > 0.3 ? double(raw[static_cast<size_t>(y * w + x)]) / nDotL : -1.0;
  };
  // Per edge pixel: is the half-resolution irradiance nearer the sphere's own (full-resolution)
  // than the floor's beside it? Only pixels where the two differ clearly count.
  int edges = 0, ownSide = 0;
  for (int y = 1; y + 1 < h; ++y) {
    for (int x = 1; x + 1 < w; ++x) {
      if (scene.truth(x, y).hit != Hit::Sphere) continue;
      const double e = irradiance(full, x, y);
      if (!(e > 0.0)) continue;
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          if (scene.truth(x + dx, y + dy).hit != Hit::Floor) continue;
          const double floorE = irradiance(full, x + dx, y + dy);
          if (!(floorE > 0.0) || std::abs(floorE - e) < 0.5) continue;
          const double halfE = irradiance(half, x, y);
          ++edges;
          if (std::abs(halfE - e) < std::abs(halfE - floorE)) ++ownSide;
        }
      }
    }
  }
  ASSERT_GT(edges, 20) << "the test needs unrelated light on the two sides";
  const double share = double(ownSide) / edges;
  std::printf("sphere edge: %d of %d (%.3f) nearer the sphere's own irradiance than the floor's\n",
              ownSide, edges, share);
  // Measured: 0.757 (56 of 74) weighted by distance, 0.568 with plain bilinear weights. The
  // rest is the reduced grid itself: two pixels apart on a surface seen edge-on are far apart on
  // it, where the irradiance differs as much as the floor's does.
  EXPECT_GT(share, 0.68);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxTileLookupResolutionTest, BadLookupSettingsAreRefusedByName) {
  postfxtest::SceneSpec spec;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.05);
  auto fx = postfxtest::makeContext(kRaw);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2, {}, 0.0);
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  scene.clearTarget(glm::vec4(0.25f));
  frame.caustics.tileLookupResolution = static_cast<CausticsLookupResolution>(3);
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(fx.get())).find("caustics.tileLookupResolution"),
            std::string::npos)
      << postfx::lastError(fx.get());
  frame.caustics.tileLookupResolution = CausticsLookupResolution::Half;
  for (int points : {0, 3, -1}) {
    frame.caustics.tilePointsPerTexel = points;
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument) << points;
    EXPECT_NE(std::string(postfx::lastError(fx.get())).find("caustics.tilePointsPerTexel"),
              std::string::npos)
        << postfx::lastError(fx.get());
  }
  // Nothing was drawn.
  const auto target = postfxtest::readRgba(scene.target, spec.width, spec.height);
  for (const glm::vec4& p : target) ASSERT_EQ(p, glm::vec4(0.25f));
  glDeleteTextures(1, &water);
}

}  // namespace
