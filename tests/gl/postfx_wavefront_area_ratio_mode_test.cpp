// The WavefrontAreaRatio caustics model on its own terms: flat water gives 1, the
// mesh conserves flux, the clamp's reported bias is what it removed, the caustics pass really
// samples the irradiance, no light where there must be none, and bad settings fail cleanly.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "postfx_wavefront_area_ratio_util.h"

namespace {

using postfxtest::kPhysical;

class PostfxWavefrontAreaRatioTest : public testsupport::GlTest {};

bool allFinite(const std::vector<float>& v) {
  return std::all_of(v.begin(), v.end(), [](float x) { return std::isfinite(x); });
}

TEST_F(PostfxWavefrontAreaRatioTest, FlatWaterGivesOneEverywhere) {
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.0);
  auto fx = postfxtest::makeContext(kPhysical);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
  postfxtest::useWavefrontAreaRatio(frame, 128, 3, 9.0f);
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const postfx::testing::CausticIrradianceInfo info = postfx::testing::causticIrradiance(*fx);
  ASSERT_NE(info.texture, 0u);
  EXPECT_EQ(info.resolution, 128);
  EXPECT_EQ(info.layers, 3);
  const std::vector<float> e = postfxtest::readIrradiance(info);
  // Flat water maps every triangle onto a translated copy of itself: ratio 1 up to the float
  // rounding of the screen derivatives (~1e-5), and the triangles tile the window exactly
  // (every texel centre covered once).
  double lo = 1e30, hi = -1e30;
  for (float v : e) {
    lo = std::min(lo, static_cast<double>(v));
    hi = std::max(hi, static_cast<double>(v));
  }
  std::printf("flat water: irradiance over %zu texels in [%.6f, %.6f]\n", e.size(), lo, hi);
  EXPECT_NEAR(lo, 1.0, 1e-3);
  EXPECT_NEAR(hi, 1.0, 1e-3);

  // The caustics pass: raw = E * (n . up) on the floor, = up.y here, inside the window and
  // out (the tile irradiance that continues the window also gives 1 on flat water).
  const int w = scene.spec().width, h = scene.spec().height;
  const auto raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
  const double upY = -postfx::detail::refractedSunDown(frame.sun.direction, frame.water.ior).y;
  double worst = 0.0;
  for (size_t i = 0; i < raw.size(); ++i) {
    worst = std::max(worst, std::abs(static_cast<double>(raw[i]) - upY));
  }
  std::printf("flat water: raw caustic factor deviates from up.y = %.5f by at most %.2e\n", upY,
              worst);
  EXPECT_LT(worst, 2e-3);  // R16F: 11 bits
  glDeleteTextures(1, &water);
}

// Flux: the mesh hands each triangle exactly its piece of the beam, so over one period of a
// periodic surface (one cascade whose tile is the window, the grid wider than it by the
// drift margin) the window receives one period's beam: mean irradiance = the mean Fresnel
// transmittance ratio, ~1 - 1e-3 for these slopes. (Over a window of an incommensurate
// multi-cascade sea the mean is not 1: a long swell's curvature focuses or spreads the whole
// window by ~(n-1)/n d h'' -- the reference test compares such means with the reference.)
TEST_F(PostfxWavefrontAreaRatioTest, ConservesFluxOverAPeriod) {
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  const GLuint water = postfxtest::makeWaterTexture(64, 1, 0.01);
  auto fx = postfxtest::makeContext(kPhysical);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1);
  frame.water.tileSize[0] = 16.0;  // = the window
  postfxtest::useWavefrontAreaRatio(frame, 256, 4, 16.0f, 1e4f);
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const postfx::testing::CausticIrradianceInfo info = postfx::testing::causticIrradiance(*fx);
  ASSERT_DOUBLE_EQ(info.windowOrigin.x, 0.0);
  const std::vector<float> e = postfxtest::readIrradiance(info);
  ASSERT_TRUE(allFinite(e));
  const size_t perLayer = static_cast<size_t>(info.resolution) * info.resolution;
  double deepestPeak = 0.0;
  for (int k = 0; k < info.layers; ++k) {
    double sum = 0.0, peak = 0.0;
    for (size_t i = 0; i < perLayer; ++i) {
      sum += static_cast<double>(e[k * perLayer + i]);
      peak = std::max(peak, static_cast<double>(e[k * perLayer + i]));
    }
    const double meanE = sum / static_cast<double>(perLayer);
    std::printf("flux over one period: layer %d (%.2f m): mean irradiance %.5f, peak %.1f\n", k,
                static_cast<double>(info.layerDepth[k]), meanE, peak);
    EXPECT_NEAR(meanE, 1.0, 0.01);
    deepestPeak = peak;
  }
  EXPECT_GT(deepestPeak, 2.0) << "the waves must focus light somewhere, or this proves little";
  glDeleteTextures(1, &water);
}

// The clamp bounds each triangle's irradiance (a texel where folds overlap may sum several
// clamped triangles; one that takes a sub-texel triangle's point deposit may be clamped while
// its own value stays under the clamp). What it removed -- unclamped minus clamped texels, exact
// since the rasterisation is the same -- must be what stats reports.
TEST_F(PostfxWavefrontAreaRatioTest, ReportsTheFluxTheClampRemoved) {
  auto ocean = postfxtest::makeSmallOcean(3.0);
  ASSERT_TRUE(ocean);
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  auto fx = postfxtest::makeContext(kPhysical);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
  postfxtest::useOcean(frame, *ocean);
  postfxtest::useWavefrontAreaRatio(frame, 256, 4, 16.0f, 1e4f);
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const postfx::testing::CausticIrradianceInfo info = postfx::testing::causticIrradiance(*fx);
  const std::vector<float> unclamped = postfxtest::readIrradiance(info);
  ASSERT_TRUE(allFinite(unclamped));
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  const double reportedUnclamped = postfx::stats(*fx).clampedFluxFraction;

  const float clamp = 3.0f;
  frame.caustics.maxIrradiance = clamp;
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  const std::vector<float> clamped = postfxtest::readIrradiance(info);
  double removed = 0.0, above = 0.0;
  for (size_t i = 0; i < clamped.size(); ++i) {
    const double before = static_cast<double>(unclamped[i]),
                 after = static_cast<double>(clamped[i]);
    ASSERT_LE(after, before + 1e-5 * before) << "the clamp only removes, texel " << i;
    removed += before - after;
    above += before > static_cast<double>(clamp) ? 1.0 : 0.0;
  }
  const double texels = static_cast<double>(clamped.size());
  const double removedFraction = removed / texels;
  // The count is read back a few dispatches later, never waited for: finish and poll.
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  const double reported = postfx::stats(*fx).clampedFluxFraction;
  std::printf(
      "clamp %.0f: %.0f of %.0f texels above it, removed flux fraction %.6f, reported "
      "%.6f (unclamped run reported %.2e)\n",
      static_cast<double>(clamp), above, texels, removedFraction, reported, reportedUnclamped);
  // Unclamped, only triangles refracted to exactly zero area (infinite irradiance) lose flux.
  EXPECT_LT(reportedUnclamped, 1e-4);
  EXPECT_GT(removedFraction, 1e-4) << "the clamp must be active in this test";
  // Fixed point of 1/256 texel per clamped fragment, rounded: 0.5/256 per fragment at most,
  // and float sums in the texels (1e-6 relative).
  EXPECT_NEAR(reported, removedFraction, 1e-5 + 0.5 / 256.0 * above / texels);

  frame.caustics.model = postfx::CausticsModel::RayDeviation;
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  EXPECT_EQ(postfx::stats(*fx).clampedFluxFraction, 0.0) << "no clamp in the ray-deviation model";
}

// The caustics pass's raw output on a floor at a layer's depth is that layer at the pixel's
// world xz, times n . up: where a pixel is under half a texel, the layer's cubic B-spline
// reconstruction (the magnification filter; the pixels in the octave where it blends in, and
// the outer band where the tile field takes over, are excluded here).
TEST_F(PostfxWavefrontAreaRatioTest, CausticsPassSamplesTheIrradiance) {
  auto ocean = postfxtest::makeSmallOcean(5.0);
  ASSERT_TRUE(ocean);
  const double floorDepth = 4.0;
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(floorDepth));
  auto fx = postfxtest::makeContext(kPhysical);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
  postfxtest::useOcean(frame, *ocean);
  postfxtest::useWavefrontAreaRatio(frame, 128, 2, 4.0f);  // layers at 1 and 4 m
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const postfx::testing::CausticIrradianceInfo info = postfx::testing::causticIrradiance(*fx);
  ASSERT_FLOAT_EQ(info.layerDepth[1], 4.0f);
  const std::vector<float> e = postfxtest::readIrradiance(info);
  const int n = info.resolution;
  auto texel = [&](int i, int j) {
    i = std::clamp(i, 0, n - 1);
    j = std::clamp(j, 0, n - 1);
    return static_cast<double>(e[(static_cast<size_t>(n) + j) * n + i]);  // layer 1
  };
  // The uniform cubic B-spline's weights for the four texels around a point a fraction f past
  // the second one's centre.
  auto bspline = [](double f) {
    const double w0 = (1 - f) * (1 - f) * (1 - f) / 6, w3 = f * f * f / 6;
    const double w1 = (4 - 6 * f * f + 3 * f * f * f) / 6;
    return std::array<double, 4>{w0, w1, 1 - w0 - w1 - w3, w3};
  };
  const int w = scene.spec().width, h = scene.spec().height;
  const auto raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
  const double upY = -postfx::detail::refractedSunDown(frame.sun.direction, frame.water.ior).y;
  const double radiansPerPixel = 2.0 / (std::abs(scene.projection[1][1]) * h);
  int compared = 0;
  double worst = 0.0, contrast = 0.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      const glm::dvec3 p = t.position + frame.camera.position;
      const double u = (p.x - info.windowOrigin.x) / info.windowSize * n - 0.5;
      const double v = (p.z - info.windowOrigin.y) / info.windowSize * n - 0.5;
      const double edge = std::min({u, v, n - 1.0 - u, n - 1.0 - v}) / n;
      if (edge < 0.14) continue;  // the fade band (1/8) plus a texel
      // The pixel's footprint in texels, as caustics.frag computes it.
      const double distance = glm::length(t.position);
      const double facing = std::max(std::abs(glm::dot(t.normal, t.position)) / distance, 0.25);
      const double lod = std::log2(distance * radiansPerPixel / facing * n / info.windowSize);
      if (lod > -1.01) continue;  // not the B-spline alone
      const int i = static_cast<int>(std::floor(u)), j = static_cast<int>(std::floor(v));
      const std::array<double, 4> wu = bspline(u - i), wv = bspline(v - j);
      double expected = 0.0;
      for (int b = 0; b < 4; ++b)
        for (int a = 0; a < 4; ++a) expected += wu[a] * wv[b] * texel(i - 1 + a, j - 1 + b);
      expected *= upY;
      const double got = raw[static_cast<size_t>(y) * w + x];
      // R16F raw (2^-11 relative), the GPU's 8-bit bilinear weights (1/256 of a texel step: the
      // B-spline's fetch positions are rounded to them) and the depth-reconstructed position
      // (~1e-4 m, i.e. 1e-3 texel).
      const double tolerance = 2e-3 * expected + 0.02 * std::max(1.0, expected);
      worst = std::max(worst, std::abs(got - expected) / std::max(expected, 1e-3));
      contrast = std::max(contrast, expected / upY);
      ++compared;
      EXPECT_NEAR(got, expected, tolerance) << x << "," << y;
    }
  std::printf(
      "caustics pass vs its irradiance texture: %d pixels, worst relative difference "
      "%.4f, brightest %.2f\n",
      compared, worst, contrast);
  EXPECT_GT(compared, 1000);
  EXPECT_GT(contrast, 1.5) << "the floor must show caustics";
}

// World-snapped: a camera move inside one snap step (16 texels: the coarsest mip level's texel)
// leaves the irradiance bit for bit the same (no swimming), and a move of whole steps shifts it
// by exactly those texels.
TEST_F(PostfxWavefrontAreaRatioTest, PatternStaysPutWhenTheCameraMoves) {
  auto ocean = postfxtest::makeSmallOcean(2.0);
  ASSERT_TRUE(ocean);
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  auto fx = postfxtest::makeContext(kPhysical);
  auto irradianceAt = [&](const glm::dvec3& offset, postfx::testing::CausticIrradianceInfo& info) {
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3, offset);
    postfxtest::useOcean(frame, *ocean);
    postfxtest::useWavefrontAreaRatio(frame, 128, 2, 8.0f);
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    info = postfx::testing::causticIrradiance(*fx);
    return postfxtest::readIrradiance(info);
  };
  postfx::testing::CausticIrradianceInfo a, b, c;
  const double texel = 16.0 / 128.0;
  const int stepTexels = 1 << postfx::shared::IRRADIANCE_MIP_LEVELS;
  const std::vector<float> base = irradianceAt(glm::dvec3(0.0), a);
  const std::vector<float> nudged = irradianceAt(glm::dvec3(0.3 * texel, 0.0, 0.4 * texel), b);
  const std::vector<float> moved = irradianceAt(glm::dvec3(stepTexels * texel, 0.0, 0.0), c);
  EXPECT_EQ(a.windowOrigin, b.windowOrigin);
  int differing = 0;
  for (size_t i = 0; i < base.size(); ++i) differing += base[i] != nudged[i];
  // One step to the right: texel i of the moved window is texel i + 16 of the first one. The
  // same triangles land 16 texels over, but their float positions relative to the new corner
  // round differently, so a texel centre right on a triangle edge may flip sides: a few texels
  // may differ, the pattern may not. The landing spread's taps clamp at each window's edge,
  // over the band the lookup fades out: only the texels inside it in both windows compare.
  double sumShifted = 0.0;
  int flipped = 0, compared = 0;
  const int n = a.resolution;
  const int band = static_cast<int>(float(n) * postfx::shared::IRRADIANCE_FADE_BAND);
  for (int k = 0; k < a.layers; ++k)
    for (int j = band; j < n - band; ++j)
      for (int i = band; i + stepTexels < n - band; ++i) {
        const size_t at = (static_cast<size_t>(k) * n + j) * n;
        const double d = std::abs(static_cast<double>(moved[at + i]) -
                                  static_cast<double>(base[at + i + stepTexels]));
        sumShifted += d;
        flipped += d > 1e-3;
        ++compared;
      }
  std::printf(
      "camera nudged 0.3 texel: %d texels differ; moved 16 texels: %d of %d texels "
      "differ by > 1e-3, mean difference %.2e\n",
      differing, flipped, compared, sumShifted / compared);
  EXPECT_EQ(differing, 0);
  EXPECT_LT(flipped, compared / 100);
  EXPECT_LT(sumShifted / compared, 1e-3);
  EXPECT_DOUBLE_EQ(c.windowOrigin.x - a.windowOrigin.x, stepTexels * texel);
}

TEST_F(PostfxWavefrontAreaRatioTest, NoneAboveWaterOnSkyAndNanFree) {
  // Camera 2 m under a level at -0.5, a sphere breaking the surface, the sky.
  postfxtest::SceneSpec spec;
  spec.lookDirection = {0.0, -0.1, -1.0};
  spec.sphereCenter = {2.0, 0.5, -8.0};
  postfxtest::Scene scene(spec);
  const int w = spec.width, h = spec.height;
  for (bool nanWater : {false, true}) {
    SCOPED_TRACE(nanWater ? "NaN water texels" : "wavy water");
    const GLuint water = postfxtest::makeWaterTexture(64, 3, nanWater ? 0.0 : 0.01, nanWater);
    auto fx = postfxtest::makeContext(kPhysical);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
    postfxtest::useWavefrontAreaRatio(frame, 64, 3, 12.0f, 32.0f);
    scene.clearTarget(glm::vec4(0.0f));
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    const std::vector<float> e =
        postfxtest::readIrradiance(postfx::testing::causticIrradiance(*fx));
    EXPECT_TRUE(allFinite(e));
    const auto raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
    const auto target = postfxtest::readRgba(scene.target, w, h);
    const double levelRel = -0.5 - spec.camera.y;
    int sky = 0, above = 0, lit = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const size_t i = static_cast<size_t>(y) * w + x;
        const postfxtest::PixelTruth& t = scene.truth(x, y);
        ASSERT_TRUE(std::isfinite(raw[i]) && raw[i] >= 0.0f && raw[i] <= 32.0f) << raw[i];
        ASSERT_TRUE(std::isfinite(target[i].r) && std::isfinite(target[i].g) &&
                    std::isfinite(target[i].b));
        if (t.hit == postfxtest::Hit::Sky) {
          ++sky;
          EXPECT_EQ(raw[i], 0.0f);
        } else if (t.position.y > levelRel + 1e-3) {
          ++above;
          EXPECT_EQ(raw[i], 0.0f);
        } else if (raw[i] > 0.0f) {
          ++lit;
        }
      }
    std::printf("%s: %d sky and %d above-water pixels dark, %d lit, irradiance finite\n",
                nanWater ? "NaN water" : "wavy water", sky, above, lit);
    EXPECT_GT(sky, 50);
    EXPECT_GT(above, 50);
    EXPECT_GT(lit, 500) << "NaN texels read as flat water, which still lets light through";
    glDeleteTextures(1, &water);
  }
}

TEST_F(PostfxWavefrontAreaRatioTest, BadSettingsFailCleanly) {
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.01);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Case {
    const char* name;
    const char* mentions;
    void (*spoil)(postfx::CausticsSettings&, float);
  };
  const Case cases[] = {
      {"grid 0", "gridResolution",
       [](postfx::CausticsSettings& s, float) { s.gridResolution = 0; }},
      {"grid 2000", "gridResolution",
       [](postfx::CausticsSettings& s, float) { s.gridResolution = 2000; }},
      {"NaN clamp", "maxIrradiance",
       [](postfx::CausticsSettings& s, float q) { s.maxIrradiance = q; }},
      {"clamp below 1", "maxIrradiance",
       [](postfx::CausticsSettings& s, float) { s.maxIrradiance = 0.5f; }},
      {"no layers", "depthLayers", [](postfx::CausticsSettings& s, float) { s.depthLayers = 0; }},
      {"NaN window", "windowSize", [](postfx::CausticsSettings& s, float q) { s.windowSize = q; }},
      {"NaN depth", "maxReceiverDepth",
       [](postfx::CausticsSettings& s, float q) { s.maxReceiverDepth = q; }},
      {"bogus model", "model",
       [](postfx::CausticsSettings& s, float) { s.model = static_cast<postfx::CausticsModel>(7); }},
  };
  auto fx = postfxtest::makeContext(kPhysical);
  const glm::vec4 marker(0.125f, 0.25f, 0.5f, 1.0f);
  postfxtest::HostState host;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
    postfxtest::useWavefrontAreaRatio(frame, 128, 2, 8.0f);
    c.spoil(frame.caustics, nan);
    scene.clearTarget(marker);
    host.set();
    const postfxtest::GlSnapshot before = postfxtest::snapshotGlState();
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument);
    const std::string message = postfx::lastError(fx.get());
    std::printf("%s: %s\n", c.name, message.c_str());
    EXPECT_NE(message.find(c.mentions), std::string::npos) << message;
    const postfxtest::GlSnapshot after = postfxtest::snapshotGlState();
    for (const auto& [name, value] : before) EXPECT_EQ(value, after.at(name)) << name;
    host.reset();
    for (const glm::vec4& t :
         postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height))
      ASSERT_EQ(t, marker) << "something was drawn";
  }
  EXPECT_EQ(postfx::testing::causticIrradiance(*fx).texture, 0u) << "no irradiance pass ran";
  EXPECT_EQ(postfx::stats(*fx).framesDispatched, 0u);

  // The model without the feature that builds its resources.
  auto plain = postfxtest::makeContext(postfx::Feature::Caustics);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
  postfxtest::useWavefrontAreaRatio(frame, 128, 2, 8.0f);
  EXPECT_EQ(postfx::dispatch(*plain, frame), postfx::Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(plain.get())).find("Feature::WavefrontAreaRatio"),
            std::string::npos);
  glDeleteTextures(1, &water);
}

// A physical frame leaves the host's GL state (SSBO bindings included) as it found it, and the
// extra pass is timed under its own name next to the others.
TEST_F(PostfxWavefrontAreaRatioTest, RestoresStateAndTimesItsPass) {
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.01);
  auto fx = postfxtest::makeContext(kPhysical | postfx::Feature::GodRays);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
  postfxtest::useWavefrontAreaRatio(frame, 64, 2, 8.0f);
  postfxtest::HostState host;
  host.set();
  const postfxtest::GlSnapshot before = postfxtest::snapshotGlState();
  for (int i = 0; i < 2 * postfx::kTimerRingDepth; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    if (i == postfx::kTimerRingDepth) glFinish();
  }
  const postfxtest::GlSnapshot after = postfxtest::snapshotGlState();
  for (const auto& [name, value] : before) EXPECT_EQ(value, after.at(name)) << name;
  host.reset();
  const postfx::FrameStats& stats = postfx::stats(*fx);
  EXPECT_TRUE(stats.pass(postfx::Pass::Caustics).present);
  EXPECT_TRUE(stats.pass(postfx::Pass::GodRays).present);
  EXPECT_TRUE(stats.pass(postfx::Pass::WavefrontAreaRatio).present);
  EXPECT_FALSE(stats.pass(postfx::Pass::Floor).present);
  EXPECT_FALSE(stats.pass(postfx::Pass::ObjectCaustics).present);
  EXPECT_TRUE(stats.pass(postfx::Pass::TileIrradiance).present);
  EXPECT_FALSE(stats.pass(postfx::Pass::TileIrradiance).skipped)
      << "the tile irradiance continues the window: its pre-pass runs and is timed";
  std::printf(
      "timings: caustics %.3f ms, god_rays %.3f ms, caustics_irradiance %.3f ms, "
      "caustics_tile_irradiance %.3f ms (%llu frames resolved)\n",
      stats.pass(postfx::Pass::Caustics).medianMs, stats.pass(postfx::Pass::GodRays).medianMs,
      stats.pass(postfx::Pass::WavefrontAreaRatio).medianMs,
      stats.pass(postfx::Pass::TileIrradiance).medianMs,
      static_cast<unsigned long long>(stats.framesResolved));
  EXPECT_GT(stats.framesResolved, 0u);
  EXPECT_GT(stats.pass(postfx::Pass::WavefrontAreaRatio).lastMs, 0.0);
  EXPECT_FALSE(stats.pass(postfx::Pass::WavefrontAreaRatio).skipped);
  glDeleteTextures(1, &water);
}

// The landing spread (the slopes inside the grid's cells and the sun's disc) blurs each layer:
// the mean light is kept, the contrast never rises, and the deeper layer loses more of it (the
// spread grows with depth; at 2 m these cells' ripples have not folded and the disc's spread is
// under a hundredth of a texel, so that layer is left as it is: 0.318 both, 0.923 -> 0.722 at
// 8 m). Compared inside the fade band, where no tap reaches the edge.
TEST_F(PostfxWavefrontAreaRatioTest, LandingSpreadKeepsTheMeanAndSoftensDeeperLayersMore) {
  auto ocean = postfxtest::makeSmallOcean(2.0);
  ASSERT_TRUE(ocean);
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  auto fx = postfxtest::makeContext(kPhysical);
  auto layers = [&](bool unresolved, float sunDegrees,
                    postfx::testing::CausticIrradianceInfo& info) {
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
    postfxtest::useOcean(frame, *ocean);
    postfxtest::useWavefrontAreaRatio(frame, 128, 2, 8.0f);
    frame.caustics.tileUnresolvedSpread = unresolved;
    frame.sun.angularDiameterDegrees = sunDegrees;
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    info = postfx::testing::causticIrradiance(*fx);
    return postfxtest::readIrradiance(info);
  };
  postfx::testing::CausticIrradianceInfo info;
  const std::vector<float> sharp = layers(false, 0.0f, info);
  const std::vector<float> spread = layers(true, 0.53f, info);
  const int n = info.resolution;
  const int band = static_cast<int>(float(n) * postfx::shared::IRRADIANCE_FADE_BAND);
  auto moments = [&](const std::vector<float>& v, int k, double& mean, double& contrast) {
    double sum = 0.0, squares = 0.0;
    int count = 0;
    for (int j = band; j < n - band; ++j)
      for (int i = band; i < n - band; ++i) {
        const double e = v[(static_cast<size_t>(k) * n + j) * n + i];
        sum += e;
        squares += e * e;
        ++count;
      }
    mean = sum / count;
    contrast = std::sqrt(std::max(squares / count - mean * mean, 0.0)) / mean;
  };
  double softening[2] = {};
  for (int k = 0; k < info.layers; ++k) {
    double sharpMean, sharpContrast, spreadMean, spreadContrast;
    moments(sharp, k, sharpMean, sharpContrast);
    moments(spread, k, spreadMean, spreadContrast);
    std::printf("layer %d: mean %.4f -> %.4f, contrast %.3f -> %.3f\n", k, sharpMean, spreadMean,
                sharpContrast, spreadContrast);
    EXPECT_NEAR(spreadMean, sharpMean, 0.01 * sharpMean) << "layer " << k;
    EXPECT_LE(spreadContrast, sharpContrast) << "layer " << k;
    softening[k] = spreadContrast / sharpContrast;
  }
  EXPECT_LT(softening[1], softening[0]) << "the deeper layer is spread more";
  for (float e : spread) ASSERT_TRUE(std::isfinite(e) && e >= 0.0f);
}

// Every pass of a WavefrontAreaRatio frame reports a time within the wall-clock time of the
// dispatches that produced it: a query whose start was never written reads as the GPU clock's
// absolute time (llvmpipe read 11,000 s for the tile field's pass with the spread dispatched
// after the window's last layer was detached).
TEST_F(PostfxWavefrontAreaRatioTest, EveryPassTimeIsWithinTheFramesWallTime) {
  auto ocean = postfxtest::makeSmallOcean(2.0);
  ASSERT_TRUE(ocean);
  postfxtest::Scene scene(postfxtest::wavefrontAreaRatioScene(6.0));
  auto fx = postfxtest::makeContext(kPhysical | postfx::testing::BenchmarkFloor);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, 0, 3);
  postfxtest::useOcean(frame, *ocean);
  postfxtest::useWavefrontAreaRatio(frame, 128, 2, 8.0f);
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < postfx::kTimerRingDepth + 2; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    glFinish();
  }
  const double wallMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const postfx::FrameStats& s = postfx::stats(*fx);
  ASSERT_GE(s.framesResolved, 1u);
  for (postfx::Pass p : {postfx::Pass::WavefrontAreaRatio, postfx::Pass::TileIrradiance,
                         postfx::Pass::Caustics, postfx::Pass::Floor}) {
    EXPECT_FALSE(s.pass(p).skipped) << postfx::toString(p);
    EXPECT_GT(s.pass(p).lastMs, 0.0) << postfx::toString(p);
    EXPECT_LT(s.pass(p).lastMs, wallMs) << postfx::toString(p);
  }
}

}  // namespace
