// The traced frame reference's reflected light above the water (FrameTraceDesc::reflected) on
// scenes with known answers: a flat sea mirrors the sun onto an underside and a wall exactly as
// max(n . l_r, 0) / |l_r.y| says, a wave's reflected and refracted flux add up to the sun's, no
// reflected light lands under the water or on faces turned away from it, two seeds agree within
// the stated noise, any thread count gives the same bits, and the refracted light is bit for bit
// what it is without reflection. Tiny images so each case runs in seconds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "caustic_light_units.h"
#include "frame_caustics_reference.h"
#include "reference_reflection_frames.h"
#include "reference_test_surfaces.h"
#include "seabed_reference.h"

namespace {

using namespace ocean::reference;
using referencetest::ceiling;
using referencetest::FlatSurface;
using referencetest::FresnelMeans;
using referencetest::meanFresnelRatios;
using referencetest::quad;
using referencetest::reflectedDesc;
using referencetest::SineSurface;
using referencetest::TracedView;
using referencetest::traceView;
using referencetest::View;

// Traced reflected light against a constant expected value over `pixels`: rms of the errors in
// stated standard errors, the worst error, the mean.
struct Agreement {
  double rmsZ = 0.0, worst = 0.0, mean = 0.0;
  size_t pixels = 0;
};

Agreement agreement(const FrameTraceResult& r, const std::vector<size_t>& pixels, double expected) {
  Agreement a;
  double sumZ2 = 0.0;
  for (size_t i : pixels) {
    const double error = r.reflectedIrradiance[i] - expected;
    sumZ2 += error * error / (r.reflectedStandardError[i] * r.reflectedStandardError[i]);
    a.worst = std::max(a.worst, std::abs(error));
    a.mean += r.reflectedIrradiance[i];
  }
  a.pixels = pixels.size();
  a.mean /= static_cast<double>(pixels.size());
  a.rmsZ = std::sqrt(sumZ2 / static_cast<double>(pixels.size()));
  return a;
}

// The mean over a frame's pixels and its standard error: from the pixels' own errors as if
// independent, doubled because neighbouring pixels share photons (a kernel spans about pi
// pixels, which would make it sqrt(pi) = 1.8 times larger).
struct PixelMean {
  double mean = 0.0, error = 0.0;
};

PixelMean pixelMean(const std::vector<double>& values, const std::vector<double>& errors) {
  PixelMean m;
  double squares = 0.0;
  for (size_t i = 0; i < values.size(); ++i) {
    m.mean += values[i];
    squares += errors[i] * errors[i];
  }
  const double n = static_cast<double>(values.size());
  m.mean /= n;
  m.error = 2.0 * std::sqrt(squares) / n;
  return m;
}

TEST(FrameReferenceReflected, FlatSeaLightsAnUndersideWithItsMirrorLight) {
  // A plate 2 m above a flat sea facing down, narrower along the sun than its own shadow is
  // from the water it is lit by (so all of it is lit), seen from 1.5 m below it. Flat water
  // mirrors onto a face of normal (0, -1, 0) max(n . l_r, 0) / |l_r.y| = 1.
  const FlatSurface water;
  View view;
  view.eye = {0.0, 0.5, 0.0};
  view.forward = {0.0, 1.0, 0.0};
  view.up = {1.0, 0.0, 0.0};
  const TracedView t =
      traceView(water, {ceiling(-1.0, 1.0, -3.0, 3.0, 2.0)}, view, reflectedDesc({0.6, 1.0, 0.0}));
  const FrameTraceResult& r = t.result;
  ASSERT_EQ(r.reflectedIrradiance.size(), t.receivers.size());
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.litPixels, 0u);
  std::vector<size_t> pixels;
  for (size_t i = 0; i < t.receivers.size(); ++i) {
    ASSERT_TRUE(t.receivers.above[i] && r.reflectedLit[i]) << "pixel " << i;
    EXPECT_NEAR(r.flatReflected[i], 1.0, 1e-12);
    EXPECT_EQ(r.irradiance[i], 0.0);  // no receiver under the water
    pixels.push_back(i);
  }
  const Agreement a = agreement(r, pixels, 1.0);
  std::printf("flat sea, underside: mean %.5f, worst |E - 1| = %.4f, rms %.2f stated errors\n",
              a.mean, a.worst, a.rmsZ);
  // As for the refracted light (reference_frame_test.cpp): per-pixel errors from 8 batches
  // scatter like Student's t with 7 degrees of freedom; the mean is 1.
  EXPECT_LT(a.rmsZ, 1.5);
  EXPECT_LT(a.worst, 3.0 * r.reflectedNoiseQuantile);
  EXPECT_NEAR(a.mean, 1.0, 2e-3);
  EXPECT_EQ(r.reflectedBackOfWavePhotons + r.reflectedIntoWaterPhotons, 0u);
}

TEST(FrameReferenceReflected, FlatSeaLightsAWallFacingTheSunAsTheMirrorDoes) {
  // A wall standing in a flat sea, facing the sun (normal (1, 0, 0), sun toward +x), seen
  // from 3 m in front of it above the water (0.4 m to 3 m of its height). The mirror image
  // of the sun lights it with n . l_r / |l_r.y| = sun.x / sun.y = 0.6.
  const FlatSurface water;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.6, 1.0, 0.0));
  View view;
  view.eye = {3.0, 1.7, 0.0};
  view.forward = {-1.0, 0.0, 0.0};
  view.up = {0.0, 1.0, 0.0};
  view.fovY = 0.8;
  const TracedView t =
      traceView(water, {quad({0, -2, -4}, {0, 4, -4}, {0, 4, 4}, {0, -2, 4}, {1, 0, 0})}, view,
                reflectedDesc(sun));
  const FrameTraceResult& r = t.result;
  EXPECT_TRUE(r.converged);
  const double expected = sun.x / sun.y;
  std::vector<size_t> pixels;
  for (size_t i = 0; i < t.receivers.size(); ++i) {
    ASSERT_TRUE(t.receivers.above[i] && r.reflectedLit[i]) << "pixel " << i;
    EXPECT_NEAR(r.flatReflected[i], expected, 1e-12);
    pixels.push_back(i);
  }
  const Agreement a = agreement(r, pixels, expected);
  std::printf(
      "flat sea, wall: mean %.5f (expected %.5f), worst error %.4f, rms %.2f stated errors\n",
      a.mean, expected, a.worst, a.rmsZ);
  EXPECT_LT(a.rmsZ, 1.5);
  EXPECT_LT(a.worst, 3.0 * r.reflectedNoiseQuantile * expected);
  EXPECT_NEAR(a.mean / expected, 1.0, 2e-3);
}

TEST(FrameReferenceReflected, AWallsKernelsAtTheWaterlineCountOnlyTheirPartAboveIt) {
  // The same wall seen from 0.3 m above the water with kernels four pixels wide, so that the
  // lower rows' discs reach under the level, where no reflected light lands. Each kernel is
  // normalised by its weight above the level: those rows get flat water's 0.6 too, not the
  // 10-30 % less an uncorrected disc would give.
  const FlatSurface water;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.6, 1.0, 0.0));
  View view;
  view.eye = {3.0, 0.3, 0.0};
  view.forward = {-1.0, 0.0, 0.0};
  view.up = {0.0, 1.0, 0.0};
  view.fovY = 0.8;
  FrameTraceDesc desc = reflectedDesc(sun);
  desc.kernelScale = 4.0;
  const TracedView t = traceView(
      water, {quad({0, -2, -4}, {0, 4, -4}, {0, 4, 4}, {0, -2, 4}, {1, 0, 0})}, view, desc);
  const FrameTraceResult& r = t.result;
  const double expected = sun.x / sun.y;
  std::vector<double> values, errors;
  double uncorrected = 0.0;  // the mean share of their kernels above the level
  for (size_t i = 0; i < t.receivers.size(); ++i) {
    const double height = -t.receivers.depthBelow(i), radius = r.kernelRadius[i];
    if (!t.receivers.above[i] || height > 0.8 * radius) continue;
    ASSERT_TRUE(r.reflectedLit[i]);
    values.push_back(r.reflectedIrradiance[i] / expected);
    errors.push_back(r.reflectedStandardError[i] / expected);
    // The Epanechnikov kernel's weight above a chord d = height from its centre.
    const double x = height / radius, root = std::sqrt(1.0 - x * x);
    uncorrected +=
        0.5 + 8.0 / (3.0 * referencetest::kPi) *
                  (x * root * root * root / 4.0 + 3.0 * x * root / 8.0 + 3.0 * std::asin(x) / 8.0);
  }
  ASSERT_GT(values.size(), 40u);
  uncorrected /= static_cast<double>(values.size());
  const PixelMean m = pixelMean(values, errors);
  std::printf(
      "waterline: %zu pixels whose kernels reach under the level: %.4f +- %.4f of flat water's "
      "mirror light (an uncorrected kernel would give %.3f)\n",
      values.size(), m.mean, m.error, uncorrected);
  EXPECT_LT(uncorrected, 1.0 - 5.0 * m.error) << "the correction must matter, or the test proves "
                                                 "nothing";
  EXPECT_NEAR(m.mean, 1.0, 3.0 * m.error);
}

// A wave with crests along z, the sun at 45 degrees across them.
const glm::dvec3 kWaveSun = glm::normalize(glm::dvec3(1.0, 1.0, 0.0));
constexpr double kWavelength = 2.0, kWaveSlope = 0.12;

// A ceiling 6 m above the wave, x in [-1, 5], seen from below over exactly x in [0, 4] (two
// wavelengths). The ceiling shades the water over x in [-7, -1]; its window is lit by water
// 6 m toward the sun (x in about [3, 13]), so its light is the wave's periodic mirror light.
struct CeilingFrame {
  std::vector<TriangleMesh> scene{ceiling(-1.0, 5.0, -50.0, 50.0, 6.0)};
  View view;
  CeilingFrame() {
    view.forward = {0.0, 1.0, 0.0};
    view.up = {0.0, 0.0, 1.0};  // image x along world x
    view.eye = {2.0, 6.0 - 2.0 * kWavelength / view.widthAt(1.0), 0.0};
  }
};

TEST(FrameReferenceReflected, AWavesReflectedAndRefractedFluxAddUpToTheSuns) {
  const SineSurface water = SineSurface::withSlope(kWaveSlope, kWavelength);
  const double ior = 1.333;
  // Setup check: every water point whose mirror light can reach the window (within any kernel)
  // is sunlit past the ceiling, so the window sees the wave's periodic pattern.
  const CeilingFrame frame;
  for (int i = 0; i < 400000; ++i) {
    const double x = -10.0 + 30.0 * i / 400000.0;
    const SurfaceSample at = water.sample(x, 0.0);
    const glm::dvec3 n = glm::normalize(glm::dvec3(-at.slopeX, 1.0, 0.0));
    const glm::dvec3 up = glm::reflect(-kWaveSun, n);
    const double landing = x + (6.0 - at.height) * up.x / up.y;
    if (landing < -0.5 || landing > 4.5) continue;
    ASSERT_GT(x + (6.0 - at.height) * kWaveSun.x / kWaveSun.y, 5.0) << "water at x = " << x;
  }
  // Four times the pixels and a fixed 32 batches: the flux is a mean over the frame, wanted to
  // better than its pixels' noise.
  View view = frame.view;
  view.width = 96;
  view.height = 64;
  FrameTraceDesc mirrorDesc = reflectedDesc(kWaveSun);
  mirrorDesc.minBatches = mirrorDesc.maxBatches = 32;
  const TracedView above = traceView(water, frame.scene, view, mirrorDesc);

  // The refracted light on a seabed 2 m down, seen from above over two wavelengths (more
  // batches: its mean carries 35 times the reflected one's weight in the sum).
  View down;
  down.width = 96;
  down.height = 64;
  down.eye = {2.0, 0.0, 0.0};
  down.eye.y = 2.0 * kWavelength / down.widthAt(1.0) - 2.0;
  FrameTraceDesc desc = reflectedDesc(kWaveSun);
  desc.reflected = false;
  desc.minBatches = desc.maxBatches = 64;
  const TracedView below = traceView(
      water,
      {referencetest::quad({-50, -2, -50}, {50, -2, -50}, {50, -2, 50}, {-50, -2, 50}, {0, 1, 0})},
      down, desc);

  double lo = 1e30, hi = 0.0;
  for (size_t i = 0; i < above.receivers.size(); ++i) {
    ASSERT_TRUE(above.receivers.above[i]);
    lo = std::min(lo, above.result.reflectedIrradiance[i]);
    hi = std::max(hi, above.result.reflectedIrradiance[i]);
  }
  for (size_t i = 0; i < below.receivers.size(); ++i) ASSERT_TRUE(below.receivers.valid[i]);
  const PixelMean reflected =
      pixelMean(above.result.reflectedIrradiance, above.result.reflectedStandardError);
  const PixelMean transmitted = pixelMean(below.result.irradiance, below.result.standardError);
  const FresnelMeans expected = meanFresnelRatios(water, kWavelength, kWaveSun, ior);
  const double rFlat = fresnelReflectance(kWaveSun.y, ior);
  const double tFlat = fresnelTransmittance(kWaveSun.y, ior);
  const double total = rFlat * reflected.mean + tFlat * transmitted.mean;
  const double totalError = std::hypot(rFlat * reflected.error, tFlat * transmitted.error);
  std::printf(
      "wave flux: reflected %.5f +- %.5f (expected %.5f; min %.3f max %.3f), transmitted %.6f +- "
      "%.6f (expected %.6f); R_flat %.5f T_flat %.5f: reflected + transmitted = %.6f +- %.6f of "
      "the sun's\n",
      reflected.mean, reflected.error, expected.reflected, lo, hi, transmitted.mean,
      transmitted.error, expected.transmitted, rFlat, tFlat, total, totalError);
  EXPECT_GT(hi / lo, 1.5) << "the wave must modulate the reflected light, or the test proves "
                             "nothing";
  EXPECT_GT(std::abs(expected.reflected - 1.0), 0.01) << "the wave's Fresnel mean must differ";
  // No photon lost: none met the back of a wave or was mirrored back into the water.
  EXPECT_EQ(above.result.reflectedBackOfWavePhotons, 0u);
  EXPECT_EQ(above.result.reflectedIntoWaterPhotons, 0u);
  EXPECT_EQ(above.result.reflectedReboundPhotons, 0u);
  EXPECT_EQ(below.result.backOfWavePhotons, 0u);
  // Each mean against its Fresnel average, and their sum against the sun's flux: the reflected
  // within 0.5 %, the refracted and the sum (which carries the refracted 35 times more) within
  // 1e-3; the noise small enough that each bound is at least 3.3 of its standard errors.
  EXPECT_LT(reflected.error, 1.5e-3);
  EXPECT_LT(transmitted.error, 3e-4);
  EXPECT_LT(totalError, 3e-4);
  EXPECT_NEAR(reflected.mean / expected.reflected, 1.0, 5e-3);
  EXPECT_NEAR(transmitted.mean / expected.transmitted, 1.0, 1e-3);
  EXPECT_NEAR(total, 1.0, 1e-3);
}

TEST(FrameReferenceReflected, TwoSeedsAgreeWithinTheStatedReflectedNoise) {
  const SineSurface water = SineSurface::withSlope(kWaveSlope, kWavelength);
  const CeilingFrame frame;
  FrameTraceDesc desc = reflectedDesc(kWaveSun);
  desc.seed = 1;
  const TracedView a = traceView(water, frame.scene, frame.view, desc);
  desc.seed = 2;
  const TracedView b = traceView(water, frame.scene, frame.view, desc);
  double sumZ2 = 0.0, worst = 0.0;
  size_t pixels = 0, differ = 0;
  for (size_t i = 0; i < a.receivers.size(); ++i) {
    const double sigma =
        std::hypot(a.result.reflectedStandardError[i], b.result.reflectedStandardError[i]);
    const double z = (a.result.reflectedIrradiance[i] - b.result.reflectedIrradiance[i]) / sigma;
    sumZ2 += z * z;
    worst = std::max(worst, std::abs(z));
    differ += a.result.reflectedIrradiance[i] != b.result.reflectedIrradiance[i];
    ++pixels;
  }
  const double rmsZ = std::sqrt(sumZ2 / static_cast<double>(pixels));
  std::printf("two seeds: rms difference %.3f stated sigmas, worst %.2f, %zu of %zu differ\n", rmsZ,
              worst, differ, pixels);
  EXPECT_GT(differ, pixels / 2) << "different seeds must give different photons";
  EXPECT_LT(rmsZ, 1.5);
  EXPECT_GT(rmsZ, 0.6);
  EXPECT_LT(worst, 10.0);
}

// Seen from the sun's side, above a wave: a seabed 3 m down, a wall at x = -2 facing the sun
// (it gets the mirror light) and between it and the water a roof at 1 m facing up (the light
// mirrored up meets its underside, a face turned away from it).
const SineSurface kPierWater = SineSurface::withSlope(0.15, 2.0);
const glm::dvec3 kPierSun = glm::normalize(glm::dvec3(0.6, 1.0, 0.1));

std::vector<TriangleMesh> pierScene() {
  return {quad({-50, -3, -50}, {50, -3, -50}, {50, -3, 50}, {-50, -3, 50}, {0, 1, 0}),
          quad({-2, -3, -4}, {-2, 4, -4}, {-2, 4, 4}, {-2, -3, 4}, {1, 0, 0}),
          quad({-1.5, 1, -2}, {0.5, 1, -2}, {0.5, 1, 2}, {-1.5, 1, 2}, {0, 1, 0})};
}

View pierView() {
  View v;
  v.eye = {3.0, 4.0, 0.0};
  v.forward = glm::normalize(glm::dvec3(-4.5, -3.5, 0.0));
  v.up = glm::normalize(glm::dvec3(-3.5, 4.5, 0.0));
  v.fovY = 1.0;
  return v;
}

TEST(FrameReferenceReflected, NoReflectedLightUnderTheWaterOrOnFacesTurnedAway) {
  const TracedView t = traceView(kPierWater, pierScene(), pierView(), reflectedDesc(kPierSun));
  const FrameReceivers& rc = t.receivers;
  const FrameTraceResult& r = t.result;
  size_t under = 0, roof = 0, wall = 0, wallLit = 0;
  double wallLight = 0.0;
  for (size_t i = 0; i < rc.size(); ++i) {
    if (rc.valid[i]) {  // under the water: the refracted light's, never the reflected
      ++under;
      EXPECT_EQ(r.reflectedIrradiance[i], 0.0) << "pixel " << i;
      EXPECT_EQ(r.reflectedStandardError[i], 0.0) << "pixel " << i;
      EXPECT_FALSE(r.reflectedLit[i]);
      continue;
    }
    if (!rc.above[i]) continue;
    if (rc.normal[i].y > 0.99) {  // the roof's top: light reflected up cannot reach it
      ++roof;
      EXPECT_EQ(r.reflectedIrradiance[i], 0.0) << "pixel " << i;
      EXPECT_EQ(r.flatReflected[i], 0.0);
      EXPECT_FALSE(r.reflectedLit[i]);
    } else if (rc.normal[i].x > 0.99) {
      ++wall;
      wallLit += r.reflectedLit[i];
      if (r.reflectedLit[i]) wallLight += r.reflectedIrradiance[i];
    }
  }
  std::printf("under the water %zu, roof %zu, wall %zu (%zu mirror-lit, mean light %.3f)\n", under,
              roof, wall, wallLit, wallLit > 0 ? wallLight / static_cast<double>(wallLit) : 0.0);
  EXPECT_GT(under, 200u);
  EXPECT_GT(roof, 100u);
  EXPECT_GT(wallLit, 100u);
  EXPECT_LT(wallLit, wall) << "the roof must shade part of the wall from the mirror light";
  // The control: the same photons do light the wall (flat water: sun.x / sun.y = 0.6).
  EXPECT_GT(wallLight / static_cast<double>(wallLit), 0.3);
  EXPECT_GT(r.reflectedPhotonsPerBatch, 1000u);
}

TEST(FrameReferenceReflected, AnyThreadCountGivesTheSameBits) {
  FrameTraceDesc desc = reflectedDesc(kPierSun);
  desc.maxBatches = 2;
  desc.sunAngularRadius = 0.0046;
  View view = pierView();
  view.width = 24;
  view.height = 16;
  desc.threads = 1;
  const TracedView one = traceView(kPierWater, pierScene(), view, desc);
  desc.threads = 3;
  const TracedView three = traceView(kPierWater, pierScene(), view, desc);
  EXPECT_EQ(one.result.reflectedIrradiance, three.result.reflectedIrradiance);
  EXPECT_EQ(one.result.reflectedStandardError, three.result.reflectedStandardError);
  EXPECT_EQ(one.result.irradiance, three.result.irradiance);
  double sum = 0.0;
  for (double e : one.result.reflectedIrradiance) sum += e;
  EXPECT_GT(sum, 0.0) << "the frame must hold reflected light, or the test proves nothing";
}

TEST(FrameReferenceReflected, TheRefractedLightIsBitForBitTheSameWithReflectionOn) {
  // The reflected launch has its own photons: the seabed's sums and every refracted result
  // stay those of a trace without it (for the same number of batches; with reflection on,
  // its noise may ask for more).
  FrameTraceDesc desc = reflectedDesc(kPierSun);
  desc.minBatches = desc.maxBatches = 3;
  desc.sunAngularRadius = 0.0046;
  const TracedView on = traceView(kPierWater, pierScene(), pierView(), desc);
  desc.reflected = false;
  const TracedView off = traceView(kPierWater, pierScene(), pierView(), desc);
  ASSERT_EQ(on.result.batches, off.result.batches);
  EXPECT_TRUE(off.result.reflectedIrradiance.empty());
  EXPECT_EQ(off.result.reflectedPhotonsPerBatch, 0u);
  EXPECT_GT(on.result.reflectedPhotonsPerBatch, 0u);
  EXPECT_EQ(on.result.irradiance, off.result.irradiance);
  EXPECT_EQ(on.result.standardError, off.result.standardError);
  EXPECT_EQ(on.result.noise, off.result.noise);
  EXPECT_EQ(on.result.lit, off.result.lit);
  EXPECT_EQ(on.result.flatIrradiance, off.result.flatIrradiance);
  EXPECT_EQ(on.result.backOfWavePhotons, off.result.backOfWavePhotons);
  EXPECT_EQ(on.result.photonsPerBatch - on.result.reflectedPhotonsPerBatch,
            off.result.photonsPerBatch);
  size_t underwater = 0;
  for (size_t i = 0; i < on.receivers.size(); ++i) {
    if (!on.receivers.valid[i]) continue;
    ++underwater;
    EXPECT_EQ(on.result.kernelRadius[i], off.result.kernelRadius[i]);
  }
  EXPECT_GT(underwater, 200u);
}

TEST(FrameReferenceReflected, FlatMirrorLightIsExactlyThePluginsFlatSeaLight) {
  // The reference's light with E_r = flatReflected must be the plugin's own over a flat sea
  // (I = 1, visibility 1): albedo E_sun intensity R(sun.y) max(n . l_r, 0), no view extinction
  // for a camera above the water; without includeMirrorMean, the waves' share only.
  postfx::FrameDesc frame;
  frame.sun.direction = glm::normalize(glm::dvec3(0.4, 1.0, -0.3));
  frame.sun.irradiance = glm::vec3(3.2f, 3.0f, 2.7f);
  frame.reflectedCaustics.intensity = 1.7f;
  frame.water.ior = 1.333f;
  frame.water.absorption = glm::vec3(0.3f, 0.1f, 0.05f);
  frame.water.level = 0.0;
  frame.camera.position = glm::dvec3(0.0, 3.0, 0.0);
  const glm::dvec3 sun = glm::normalize(glm::dvec3(frame.sun.direction));
  const glm::dvec3 down(sun.x, -sun.y, sun.z);  // l_r
  const glm::dvec3 n = glm::normalize(glm::dvec3(0.5, -1.0, 0.2));
  const double flat = std::max(glm::dot(n, down), 0.0) / sun.y;
  const glm::vec3 albedo(0.5f, 0.4f, 0.3f);
  const double r = fresnelReflectance(sun.y, 1.333);
  CausticLightUnits units = causticLightUnits(frame);
  const glm::vec3 light = referenceReflectedLight(units, albedo, -1.5, flat, flat, 12.0);
  for (int c = 0; c < 3; ++c) {
    const double expected = double(albedo[c]) * double(frame.sun.irradiance[c]) * 1.7 * r *
                            std::max(glm::dot(n, down), 0.0);
    EXPECT_NEAR(double(light[c]), expected, 1e-5 * expected) << "channel " << c;
    // The waves' modulation only: flat water's own light adds nothing, twice it adds it once.
    units.includeMirrorMean = false;
    EXPECT_EQ(referenceReflectedLight(units, albedo, -1.5, flat, flat, 12.0)[c], 0.0f);
    EXPECT_NEAR(double(referenceReflectedLight(units, albedo, -1.5, 2.0 * flat, flat, 12.0)[c]),
                expected, 1e-5 * expected);
    units.includeMirrorMean = true;
  }
  // A sun below the horizon mirrors nothing.
  frame.sun.direction = glm::vec3(0.3f, -0.2f, 0.0f);
  EXPECT_EQ(referenceReflectedLight(causticLightUnits(frame), albedo, -1.5, 1.0, 1.0, 12.0),
            glm::vec3(0.0f));
}

}  // namespace
