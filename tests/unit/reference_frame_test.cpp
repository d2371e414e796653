// The traced frame reference (sample_app/reference/frame_caustics_reference.h) on scenes with
// known answers: flat water gives the unperturbed light, a water tile conserves flux, two seeds
// agree within the stated noise, any thread count gives the same bits, and no light reaches
// surfaces above the water, the sky or a shadow. Tiny images so each case runs in seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_light_units.h"
#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"
#include "reference_test_frames.h"
#include "reference_test_surfaces.h"
#include "seabed_reference.h"

namespace {

using namespace ocean::reference;
using referencetest::baseDesc;
using referencetest::FlatSurface;
using referencetest::horizontalQuad;
using referencetest::kPi;
using referencetest::lookDown;
using referencetest::SineSurface;
using referencetest::trace;
using referencetest::Traced;

TEST(FrameReference, FlatWaterGivesTheUnperturbedLightWithinTheStatedNoise) {
  const FlatSurface water;
  const Traced t = trace(water, {horizontalQuad(-50, 50, -50, 50, -4.0)}, {0.0, -1.0, 0.0},
                         baseDesc({0.3, 1.0, 0.2}));
  const FrameTraceResult& r = t.result;
  ASSERT_GT(r.litPixels, 1000u);
  EXPECT_TRUE(r.converged);
  EXPECT_LT(r.noiseQuantile, 0.05);
  double sumZ2 = 0.0, worst = 0.0, mean = 0.0;
  for (size_t i = 0; i < t.receivers.size(); ++i) {
    ASSERT_TRUE(r.lit[i]);
    // A horizontal receiver under flat water: exactly 1 (the flat irradiance) up to noise.
    EXPECT_NEAR(r.flatIrradiance[i], 1.0, 1e-12);
    const double error = r.irradiance[i] - 1.0;
    sumZ2 += error * error / (r.standardError[i] * r.standardError[i]);
    worst = std::max(worst, std::abs(error));
    mean += r.irradiance[i];
  }
  const double pixels = static_cast<double>(t.receivers.size());
  mean /= pixels;
  const double rmsZ = std::sqrt(sumZ2 / pixels);
  std::printf("flat water: mean E %.5f, worst |E - 1| = %.4f, rms %.2f stated errors\n", mean,
              worst, rmsZ);
  // The stated errors describe the deviations (each is estimated from 8 batches, so single
  // pixels scatter like Student's t with 7 degrees of freedom: no per-pixel bound in sigmas);
  // no pixel strays beyond three times the 99th-percentile noise, and the mean is 1.
  EXPECT_LT(rmsZ, 1.5);
  EXPECT_LT(worst, 3.0 * r.noiseQuantile);
  EXPECT_NEAR(mean, 1.0, 2e-3);
}

TEST(FrameReference, FlatIrradianceIsExactlyThePluginsFlatWaterLight) {
  // The reference's light with E = flat irradiance must be the plugin's own light for flat
  // water (omega = 1, visibility 1): albedo E_sun intensity T(d) fade(d) (n.u).
  postfx::FrameDesc frame;
  frame.sun.direction = glm::normalize(glm::dvec3(0.4, 1.0, -0.3));
  frame.sun.irradiance = glm::vec3(3.2f, 3.0f, 2.7f);
  frame.caustics.intensity = 1.7f;
  frame.water.ior = 1.333f;
  const CausticLightUnits units = causticLightUnits(frame);
  const glm::dvec3 up = -refractSunRay(frame.sun.direction, 0.0, 0.0, frame.water.ior);
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.2, 1.0, 0.5));
  const double nDotL = glm::dot(n, up);
  const glm::vec3 albedo(0.5f, 0.4f, 0.3f);
  for (double depth : {0.3, 2.0, 9.0}) {
    const glm::vec3 light = referenceCausticLight(units, albedo, depth, nDotL / up.y, 0.0);
    const float fade = depth >= 1.0 ? 1.0f : static_cast<float>(depth * depth * (3 - 2 * depth));
    for (int c = 0; c < 3; ++c) {
      const double expected = double(albedo[c]) * double(frame.sun.irradiance[c]) * 1.7 *
                              std::exp(-double(frame.water.absorption[c]) * depth / up.y) *
                              double(fade) * nDotL;
      EXPECT_NEAR(double(light[c]), expected, 1e-5 * expected)
          << "depth " << depth << " channel " << c;
    }
  }
}

TEST(FrameReference, AWaterTileConservesFlux) {
  // Vertical sun through a sine wave; the view covers exactly two wavelengths along x on a flat
  // seabed beyond the paraxial focus, where the pattern is strongly modulated. The mean
  // irradiance over whole periods is the mean Fresnel transmittance ratio of the wave.
  const double n = 1.333, slope = 0.15, depth = 4.0, height = 2.0, fovY = 0.9;
  const int width = 48, rows = 32;
  const double viewWidth = 2.0 * (height + depth) * std::tan(0.5 * fovY) * width / rows;
  const SineSurface water = SineSurface::withSlope(slope, viewWidth / 2.0);
  FrameTraceDesc desc = baseDesc({0.0, 1.0, 0.0});
  const Traced t = trace(water, {horizontalQuad(-50, 50, -50, 50, -depth)}, {0.0, height, 0.0},
                         desc, width, rows, fovY);
  const FrameTraceResult& r = t.result;
  double mean = 0.0, lo = 1e30, hi = 0.0;
  for (double e : r.irradiance) {
    mean += e;
    lo = std::min(lo, e);
    hi = std::max(hi, e);
  }
  mean /= static_cast<double>(r.irradiance.size());
  const double expected = referencetest::meanTransmittanceRatio(water, viewWidth, n);
  std::printf("tile flux: mean %.6f expected %.6f (min %.3f max %.3f)\n", mean, expected, lo, hi);
  EXPECT_GT(hi / lo, 1.5) << "the wave must modulate the light, or the test proves nothing";
  EXPECT_NEAR(mean / expected, 1.0, 1e-3);
}

TEST(FrameReference, TwoSeedsAgreeWithinTheStatedNoise) {
  const SineSurface water = SineSurface::withSlope(0.2, 3.0);
  FrameTraceDesc desc = baseDesc({0.2, 1.0, 0.1});
  const std::vector<TriangleMesh> scene = {horizontalQuad(-50, 50, -50, 50, -3.0)};
  desc.seed = 1;
  const Traced a = trace(water, scene, {0.0, -0.5, 0.0}, desc);
  desc.seed = 2;
  const Traced b = trace(water, scene, {0.0, -0.5, 0.0}, desc);
  double sumZ2 = 0.0, worst = 0.0;
  size_t pixels = 0, differ = 0;
  for (size_t i = 0; i < a.receivers.size(); ++i) {
    if (!a.result.lit[i]) continue;
    const double sigma = std::hypot(a.result.standardError[i], b.result.standardError[i]);
    const double z = (a.result.irradiance[i] - b.result.irradiance[i]) / sigma;
    sumZ2 += z * z;
    worst = std::max(worst, std::abs(z));
    differ += a.result.irradiance[i] != b.result.irradiance[i];
    ++pixels;
  }
  const double rmsZ = std::sqrt(sumZ2 / static_cast<double>(pixels));
  std::printf("two seeds: rms difference %.3f stated sigmas, worst %.2f, %zu of %zu differ\n", rmsZ,
              worst, differ, pixels);
  EXPECT_GT(differ, pixels / 2) << "different seeds must give different photons";
  // The stated noise describes the differences: neither understated nor grossly overstated
  // (per-pixel estimates from 8 batches scatter like Student's t with 7 degrees of freedom,
  // whose rms is 1.18; heavy tails, hence the loose worst case).
  EXPECT_LT(rmsZ, 1.5);
  EXPECT_GT(rmsZ, 0.6);
  EXPECT_LT(worst, 10.0);
}

TEST(FrameReference, AnyThreadCountGivesTheSameBits) {
  const SineSurface water = SineSurface::withSlope(0.2, 3.0);
  FrameTraceDesc desc = baseDesc({0.2, 1.0, 0.1});
  desc.maxBatches = 1;
  const std::vector<TriangleMesh> scene = {horizontalQuad(-50, 50, -50, 50, -3.0)};
  desc.threads = 1;
  const Traced one = trace(water, scene, {0.0, -0.5, 0.0}, desc, 24, 16);
  desc.threads = 3;
  const Traced three = trace(water, scene, {0.0, -0.5, 0.0}, desc, 24, 16);
  EXPECT_EQ(one.result.irradiance, three.result.irradiance);
  EXPECT_EQ(one.result.standardError, three.result.standardError);
}

TEST(FrameReference, NoLightAboveTheWaterOnTheSkyOrInShadow) {
  // Seen from above: a seabed 3 m down covering x < 3 only (sky beyond), a platform 0.5 m above
  // the water over z < -2, and a plate floating 1 m down that shades part of the seabed. Flat
  // water, so the shadow has a sharp edge.
  const FlatSurface water;
  const std::vector<TriangleMesh> scene = {horizontalQuad(-50, 3, -50, 50, -3.0),
                                           horizontalQuad(-50, 50, -50, -2.0, 0.5),
                                           horizontalQuad(-1.0, 0.5, 0.0, 1.5, -1.0)};
  FrameTraceDesc desc = baseDesc({0.3, 1.0, 0.2});
  const int width = 48, height = 32;
  const Traced t = trace(water, scene, {0.0, 4.0, 0.0}, desc, width, height, 1.2);
  const FrameReceivers& rc = t.receivers;
  const FrameTraceResult& r = t.result;
  size_t sky = 0, above = 0, shadow = 0, lit = 0;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      if (!rc.valid[i]) {  // sky or above the water: nothing at all
        EXPECT_EQ(r.irradiance[i], 0.0);
        EXPECT_FALSE(r.lit[i]);
        (rc.normal[i] == glm::dvec3(0.0) ? sky : above) += 1;
        continue;
      }
      if (r.lit[i]) {
        ++lit;
        continue;
      }
      // Deep in the shadow (no lit pixel within 2 pixels, farther than any kernel): exactly 0.
      bool nearLight = false;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) {
          const int px = std::clamp(x + dx, 0, width - 1), py = std::clamp(y + dy, 0, height - 1);
          nearLight = nearLight || r.lit[static_cast<size_t>(py) * width + px];
        }
      if (nearLight) continue;
      ++shadow;
      EXPECT_EQ(r.irradiance[i], 0.0) << "pixel " << x << ", " << y;
    }
  }
  std::printf("sky %zu, above water %zu, deep shadow %zu, lit %zu pixels\n", sky, above, shadow,
              lit);
  EXPECT_GT(sky, 20u);
  EXPECT_GT(above, 20u);
  EXPECT_GT(shadow, 10u);
  EXPECT_GT(lit, 200u);
}

}  // namespace
