// The default model's pattern on water this project did not make. A host's own sea,
// a sum of Gerstner (trochoidal) waves with their exact heights and slopes on the texture's
// grid, drives the TileIrradiance pass on the report's flat seabed, against converged light
// tracing through the same texture (report/caustic_rows.h). On a flat seabed the irradiance
// relative to flat water is the pattern itself (nothing else varies), so the correlation here
// is a pattern correlation. The numbers are printed for the record (docs/measurements.md): the
// ripples, resolved by the texture but not by the pass's grid of this one 16 m cascade, are
// spread as unresolved slopes, and the pattern comes out too soft (contrast 0.26 against the
// trace's 0.69 at 3 m); a 512 grid resolves them (CausticsSettings::tileResolution). The
// floors hold today's agreement at both so that a regression shows; the flux is exact.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <error_metrics.h>
#include <flat_seabed_comparison.h>

#include "flat_seabed_settings.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "postfx_wavefront_area_ratio_util.h"

namespace {

constexpr double kTwoPi = 6.283185307179586;

// One trochoidal wave with whole periods per tile: (kx, kz) cycles per tile, amplitude (m),
// steepness q in [0, 1) (q = 1: the crest forms a cusp), phase.
struct GerstnerWave {
  int kx, kz;
  double amplitude, steepness, phase;
};

// The host's sea on a tile of `tile` metres: RGBA32F texels (dh/dx, dh/dz, h, 1) at texel
// centres. A Gerstner surface moves each water parcel a to a + D(a); the height at world x is
// h(a) with a + D(a) = x (found by fixed-point iteration, a contraction for sum q < 1), its
// slope J^-T grad_a h with J = I + dD/da.
std::vector<glm::vec4> gerstnerTexels(const std::vector<GerstnerWave>& waves, double tile,
                                      int size) {
  std::vector<glm::vec4> texels(static_cast<size_t>(size) * size);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const glm::dvec2 world((x + 0.5) / size * tile, (y + 0.5) / size * tile);
      glm::dvec2 a = world;
      for (int iteration = 0; iteration < 60; ++iteration) {
        glm::dvec2 d(0.0);
        for (const GerstnerWave& w : waves) {
          const glm::dvec2 k = kTwoPi / tile * glm::dvec2(w.kx, w.kz);
          const double kl = glm::length(k);
          d += -(w.steepness / kl) * (k / kl) * std::sin(glm::dot(k, a) + w.phase);
        }
        a = world - d;
      }
      double h = 0.0;
      glm::dvec2 gradA(0.0);
      glm::dmat2 jacobian(1.0);
      for (const GerstnerWave& w : waves) {
        const glm::dvec2 k = kTwoPi / tile * glm::dvec2(w.kx, w.kz);
        const double kl = glm::length(k), theta = glm::dot(k, a) + w.phase;
        h += w.amplitude * std::cos(theta);
        gradA += -w.amplitude * std::sin(theta) * k;
        // d/da of -(q / |k|) (k / |k|) sin(theta) = -(q / |k|^2) cos(theta) k k^T.
        jacobian -= (w.steepness / (kl * kl)) * std::cos(theta) * glm::outerProduct(k, k);
      }
      const glm::dvec2 slope = glm::inverse(glm::transpose(jacobian)) * gradA;
      texels[static_cast<size_t>(y) * size + x] =
          glm::vec4(float(slope.x), float(slope.y), float(h), 1.0f);
    }
  }
  return texels;
}

// The default's light on the flat seabed against the trace through the same water: the pattern
// agreement, each side's contrast and the plugin's mean over the trace's.
struct Agreement {
  ocean::validation::ErrorStats stats;
  double contrast = 0.0, traceContrast = 0.0, meanRatio = 0.0;
};
bool measure(const ocean::validation::FlatSeabedComparison& seabed,
             const postfx::CausticsSettings& caustics, Agreement& out, std::string& error) {
  postfx::CreateDesc create;
  if (caustics.model == postfx::CausticsModel::WavefrontAreaRatio)
    create.features = postfx::Feature::WavefrontAreaRatio;
  ocean::validation::PassRun run;
  std::vector<double> light;
  if (!seabed.run(create, caustics, 1, run, light, error)) return false;
  out.stats = ocean::validation::compareWithReference(light, seabed.truth());
  out.contrast = ocean::validation::contrast(light);
  out.traceContrast = ocean::validation::contrast(seabed.truth());
  out.meanRatio = postfxtest::mean(light) / postfxtest::mean(seabed.truth());
  return true;
}

// The wavefront area ratio on a 16 m window at `grid`, with the landing spread of the slopes
// inside its cells (`spread`) and with the sun's disc alone (`disc`).
bool measureWindow(const ocean::validation::FlatSeabedComparison& seabed, int grid,
                   Agreement& spread, Agreement& disc, std::string& error) {
  postfx::CausticsSettings joint;
  joint.model = postfx::CausticsModel::WavefrontAreaRatio;
  joint.gridResolution = grid;
  joint.windowSize = 16.0f;
  if (!measure(seabed, joint, spread, error)) return false;
  joint.tileUnresolvedSpread = false;
  return measure(seabed, joint, disc, error);
}

class PostfxHostWaterTest : public testsupport::GlTest {};

TEST_F(PostfxHostWaterTest, GerstnerSeaPatternAgainstTracedLight) {
  // A 16 m tile of swell, chop and ripples: wavelengths 16 m to 0.42 m (the ripples' slopes
  // about 0.08 each), crests sharpened by the trochoid.
  const double tile = 16.0;
  const int size = 512;
  const std::vector<GerstnerWave> waves = {
      {1, 0, 0.20, 0.30, 0.0},    {2, 1, 0.08, 0.30, 1.3},     {-3, 2, 0.05, 0.30, 2.1},
      {5, -4, 0.025, 0.25, 0.4},  {-7, -6, 0.015, 0.20, 5.0},  {10, 3, 0.010, 0.15, 3.3},
      {17, -9, 0.0106, 0.3, 0.7}, {-23, 14, 0.0076, 0.3, 2.9}, {31, 22, 0.0053, 0.3, 4.4}};
  const GLuint water =
      postfxtest::makeWaterTextureFromTexels(size, gerstnerTexels(waves, tile, size));
  // Per case the floor at the default grid (128 texels per tile side) and at 512, where the
  // grid resolves the ripples' focal lines.
  struct Case {
    double elevation, depth;
    double minCorrelation, minFineCorrelation;
  } cases[] = {{60.0, 3.0, 0.65, 0.85}, {60.0, 8.0, 0.72, 0.9}};
  for (const Case& c : cases) {
    postfx::FrameDesc frame;
    frame.water.texture = {water, GL_RGBA32F};
    frame.water.cascadeCount = 1;
    frame.water.tileSize[0] = tile;
    postfxtest::flatSeabedView(frame, c.elevation);
    ocean::validation::FlatSeabedComparison seabed;
    std::string error;
    ASSERT_TRUE(seabed.prepare(frame, postfxtest::flatSeabedTestSettings(c.depth), error)) << error;
    ASSERT_TRUE(seabed.reference().converged);
    for (int resolution : {128, 512}) {
      postfx::CausticsSettings caustics;  // the default: TileIrradiance
      caustics.tileResolution = resolution;
      Agreement a;
      ASSERT_TRUE(measure(seabed, caustics, a, error)) << error;
      std::printf(
          "Gerstner sea, sun %.0f deg, %.0f m, tileResolution %d: pattern correlation %.3f, "
          "relative RMSE %.3f, contrast plugin %.3f trace %.3f, mean / traced %.4f\n",
          c.elevation, c.depth, resolution, a.stats.correlation, a.stats.relativeRmse, a.contrast,
          a.traceContrast, a.meanRatio);
      EXPECT_GT(a.stats.correlation, resolution == 128 ? c.minCorrelation : c.minFineCorrelation)
          << c.elevation << " deg, " << c.depth << " m, " << resolution;
      EXPECT_NEAR(a.meanRatio, 1.0, 0.05) << "flux";
    }
    // The wavefront area ratio on grids too coarse for the ripples (cells of 16 m * 1.25 /
    // gridResolution smooth them away), with the landing spread of the slopes inside its cells.
    // The spread is the mean light of ripples that scatter it, past their folds; these are a
    // few coherent sinusoids, which at 8 m still draw (or warp) patterns of their own, and the
    // spread lowers the agreement: grid 128 at 8 m 0.796 with it, 0.829 without (contrast 0.34
    // / 0.55, the trace's 0.45); at 3 m 0.667 / 0.694, and on grid 64 at 3 m the ripples have
    // not folded: no spread. (On the FFT ocean of `seabed`, whose ripples are many, it raises
    // it: docs/measurements.md.) Asserted: the spread only softens, keeps the flux, and a
    // regression floor.
    for (int grid : {64, 128}) {
      Agreement spread, disc;
      ASSERT_TRUE(measureWindow(seabed, grid, spread, disc, error)) << error;
      std::printf(
          "Gerstner sea, sun %.0f deg, %.0f m, wavefront area ratio grid %d: pattern correlation "
          "%.3f with the unresolved slopes' spread, %.3f with the sun's disc alone; contrast "
          "%.3f / %.3f (trace %.3f); mean / traced %.4f / %.4f\n",
          c.elevation, c.depth, grid, spread.stats.correlation, disc.stats.correlation,
          spread.contrast, disc.contrast, spread.traceContrast, spread.meanRatio, disc.meanRatio);
      EXPECT_LE(spread.contrast, disc.contrast) << "the spread only softens";
      EXPECT_NEAR(spread.meanRatio, disc.meanRatio, 0.005) << "the spread keeps the flux";
      EXPECT_GT(spread.stats.correlation, c.depth > 5.0 ? 0.7 : 0.3) << grid;
    }
  }
  glDeleteTextures(1, &water);
}

// Two cascades of a host's own sea: a 16 m swell and chop, and a 2 m cascade of short waves
// whose slopes move the longer waves' light sideways by several centimetres at the seabed. The
// default multiplies the two cascades' fields (each read where the coarser one sends the
// light) instead of refracting through their sum, the assumption CausticsSettings states; this
// measures that product against the light traced through the sum, on water this project did
// not make. Measured: pattern correlation 0.833, contrast 0.655 against the trace's 0.725
// (45 deg, 4 m: 0.778). The floor keeps that from regressing; the flux is exact.
TEST_F(PostfxHostWaterTest, TwoCascadeSeaPatternAgainstTracedLight) {
  const int size = 256;
  const double swellTile = 16.0, chopTile = 2.0;
  const std::vector<GerstnerWave> swell = {{1, 0, 0.20, 0.30, 0.0},    {2, 1, 0.08, 0.30, 1.3},
                                           {-3, 2, 0.05, 0.30, 2.1},   {5, -4, 0.025, 0.25, 0.4},
                                           {-7, -6, 0.015, 0.20, 5.0}, {10, 3, 0.010, 0.15, 3.3}};
  const std::vector<GerstnerWave> chop = {
      {1, 0, 0.030, 0.2, 0.3}, {1, 2, 0.008, 0.2, 2.2}, {-3, 1, 0.004, 0.2, 4.1}};
  std::vector<glm::vec4> texels = gerstnerTexels(swell, swellTile, size);
  const std::vector<glm::vec4> fine = gerstnerTexels(chop, chopTile, size);
  texels.insert(texels.end(), fine.begin(), fine.end());
  const GLuint water = postfxtest::makeWaterTextureFromTexels(size, texels);  // two layers
  const double elevation = 60.0, depth = 6.5;
  postfx::FrameDesc frame;
  frame.water.texture = {water, GL_RGBA32F};
  frame.water.cascadeCount = 2;
  frame.water.tileSize[0] = swellTile;
  frame.water.tileSize[1] = chopTile;
  postfxtest::flatSeabedView(frame, elevation);
  ocean::validation::FlatSeabedComparison seabed;
  std::string error;
  ASSERT_TRUE(seabed.prepare(frame, postfxtest::flatSeabedTestSettings(depth), error)) << error;
  ASSERT_TRUE(seabed.reference().converged);
  Agreement a;
  ASSERT_TRUE(measure(seabed, postfx::CausticsSettings(), a, error)) << error;  // the default
  std::printf(
      "two-cascade sea, sun %.0f deg, %.1f m: pattern correlation %.3f, relative RMSE %.3f, "
      "contrast plugin %.3f trace %.3f, mean / traced %.4f\n",
      elevation, depth, a.stats.correlation, a.stats.relativeRmse, a.contrast, a.traceContrast,
      a.meanRatio);
  EXPECT_GT(a.stats.correlation, 0.8);
  EXPECT_NEAR(a.meanRatio, 1.0, 0.05) << "flux";

  // The wavefront area ratio refracts the two cascades together, which is what the product
  // leaves out: grid 512 (3.1 cm cells) measured 0.956 (contrast 0.588). Its cells resolve every
  // wave of this sea (the shortest is 0.63 m), so the landing spread of the slopes inside them
  // (the waves' curvature across 4 texels) changes next to nothing.
  Agreement spread, disc;
  ASSERT_TRUE(measureWindow(seabed, 512, spread, disc, error)) << error;
  std::printf(
      "two-cascade sea, wavefront area ratio grid 512: pattern correlation %.3f (%.3f with the "
      "sun's disc alone), relative RMSE %.3f, contrast %.3f (trace %.3f), mean / traced %.4f\n",
      spread.stats.correlation, disc.stats.correlation, spread.stats.relativeRmse, spread.contrast,
      spread.traceContrast, spread.meanRatio);
  EXPECT_GT(spread.stats.correlation, a.stats.correlation + 0.08) << "joint against product";
  EXPECT_NEAR(spread.stats.correlation, disc.stats.correlation, 0.002);
  EXPECT_NEAR(spread.contrast, disc.contrast, 0.002);
  EXPECT_NEAR(spread.meanRatio, 1.0, 0.05) << "flux";
  glDeleteTextures(1, &water);
}

}  // namespace
