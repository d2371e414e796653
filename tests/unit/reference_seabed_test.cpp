// The seabed-caustics CPU reference against cases with known answers: flat water (irradiance 1
// everywhere), a single sinusoidal wave (paraxial focus depth, flux conservation) and
// height-field seabeds.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "reference_test_surfaces.h"
#include "seabed_reference.h"

namespace {

using namespace ocean::reference;
using referencetest::FlatSurface;
using referencetest::kPi;
using referencetest::SineSurface;

ReferenceDesc quietDesc() {
  ReferenceDesc d;
  d.progress = true;
  d.ior = 1.333;
  return d;
}

TEST(SeabedReference, FlatWaterGivesOneInEveryBinWithinItsStatedError) {
  ReferenceDesc desc = quietDesc();
  desc.towardSun = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  desc.bins = {{-2.0, -2.0}, 0.25, 0.0, 16, 16};
  desc.receivers = {Receiver::flat(5.0)};
  desc.label = "reference flat water";
  const ReferenceResult r = traceSeabedCaustics(FlatSurface(), desc);
  ASSERT_EQ(r.receivers.size(), 1u);
  const ReceiverResult& out = r.receivers[0];
  double worst = 0.0, worstSigmas = 0.0;
  for (size_t i = 0; i < out.irradiance.size(); ++i) {
    const double dev = std::abs(out.irradiance[i] - 1.0);
    worst = std::max(worst, dev);
    worstSigmas = std::max(worstSigmas, dev / out.relativeError[i]);
    // 3 stated standard errors: the stated error is the Poisson bound, stratified sampling of a
    // uniform beam does far better, so this cannot fail by chance.
    EXPECT_LE(dev, 3.0 * out.relativeError[i]) << "bin " << i;
  }
  std::printf(
      "flat water: %llu rays, %d batches, median stated error %.4f %%, worst |E-1| = "
      "%.2e (%.2f stated errors), converged %d\n",
      static_cast<unsigned long long>(r.rays), r.batches, 100.0 * out.medianRelativeError, worst,
      worstSigmas, r.converged);
  EXPECT_TRUE(r.converged);
  EXPECT_LT(out.medianRelativeError, 0.01);
}

// Paraxial optics of one crest (vertical sun): the refracted ray drifts d (n-1)/n h'(x), and
// dX/dx = 1 - d (n-1)/n A k^2 reaches 0 first under the crest at f = n / ((n-1) k^2 A). The
// binned peak is brightest where the cusp forms; with bins of 1/2000 of a wavelength the two
// folds stay in the central bin for ~1.5 % beyond f, the bias of this estimator.
TEST(SeabedReference, SineWaveFocusesAtTheParaxialDepth) {
  const double n = 1.333, wavelength = 2.0, slope = 0.05;
  const SineSurface surface(slope * wavelength / (2.0 * kPi), wavelength);
  const double amplitude = slope / surface.k();
  const double focus = n / ((n - 1.0) * surface.k() * surface.k() * amplitude);
  ReferenceDesc desc = quietDesc();
  desc.ior = n;
  const double crest = wavelength / 4.0, bin = wavelength / 2000.0;
  desc.bins = {{crest - 50.5 * bin, 0.0}, bin, 1.0, 101, 1};
  std::vector<double> depths;
  for (int i = 0; i <= 60; ++i) depths.push_back(focus * (0.85 + 0.005 * i));
  for (double d : depths) desc.receivers.push_back(Receiver::flat(d));
  desc.label = "reference sine focus";
  const ReferenceResult r = traceSeabedCaustics(surface, desc);
  size_t best = 0;
  double bestPeak = 0.0;
  for (size_t i = 0; i < depths.size(); ++i) {
    const std::vector<double>& e = r.receivers[i].irradiance;
    const double peak = *std::max_element(e.begin(), e.end());
    if (peak > bestPeak) {
      bestPeak = peak;
      best = i;
    }
  }
  const double measured = depths[best];
  std::printf(
      "sine wave focus: paraxial f = %.3f m, brightest bin at %.3f m (ratio %.4f), peak "
      "irradiance %.1f, %llu rays, converged %d\n",
      focus, measured, measured / focus, bestPeak, static_cast<unsigned long long>(r.rays),
      r.converged);
  EXPECT_NEAR(measured / focus, 1.0, 0.03);
  EXPECT_GT(bestPeak, 10.0) << "a focus must concentrate the light";
}

TEST(SeabedReference, SineWaveConservesFlux) {
  const double n = 1.333, wavelength = 2.0, slope = 0.15;
  const SineSurface surface(slope / (2.0 * kPi / wavelength), wavelength);
  ReferenceDesc desc = quietDesc();
  desc.ior = n;
  desc.bins = {{0.0, 0.0}, wavelength / 100.0, 1.0, 100, 1};  // exactly one period
  const double focus = n / ((n - 1.0) * surface.k() * slope);
  desc.receivers = {Receiver::flat(0.5 * focus), Receiver::flat(focus),
                    Receiver::flat(2.0 * focus)};
  desc.label = "reference sine flux";
  const ReferenceResult r = traceSeabedCaustics(surface, desc);
  // Expected mean: the transmittance ratio averaged over one period (vertical sun: the beam's
  // cross-section per horizontal area is 1 everywhere).
  const double expected = referencetest::meanTransmittanceRatio(surface, wavelength, n);
  for (size_t i = 0; i < desc.receivers.size(); ++i) {
    const std::vector<double>& e = r.receivers[i].irradiance;
    double mean = 0.0, peak = 0.0;
    for (double v : e) {
      mean += v;
      peak = std::max(peak, v);
    }
    mean /= static_cast<double>(e.size());
    std::printf(
        "sine flux: depth %.2f m: mean irradiance %.6f, expected (mean T ratio) %.6f, "
        "relative difference %.2e, peak %.2f\n",
        desc.receivers[i].depth, mean, expected, mean / expected - 1.0, peak);
    EXPECT_NEAR(mean / expected, 1.0, 0.01);
  }
  EXPECT_TRUE(r.converged);
}

// A height-field seabed y = -D(x, z) under flat water: the refracted beam t (down) crosses any
// horizontal plane with flux 1 per unit area, and a seabed element with horizontal area dA and
// upward normal (D_x, 1, D_z) intercepts the flux of its projection along t onto that plane,
// (t . (D_x, 1, D_z)) / t_y dA. So a bin receives 1 + (t_x <D_x> + t_z <D_z>) / t_y (no
// shadowing for these slopes). And a constant height field is the flat receiver, bin for bin.
TEST(SeabedReference, HeightFieldSeabed) {
  ReferenceDesc desc = quietDesc();
  desc.towardSun = glm::normalize(glm::dvec3(0.4, 1.0, -0.1));
  desc.bins = {{0.0, 0.0}, 0.25, 0.0, 12, 12};
  Receiver bumpy;
  bumpy.depth = 6.0;  // max
  bumpy.minDepth = 4.0;
  auto depthAt = [](double x, double z) { return 5.0 + 0.9 * std::sin(1.3 * x) * std::cos(z); };
  bumpy.depthAt = depthAt;
  bumpy.featureSize = 0.2;
  desc.receivers = {bumpy};
  desc.label = "reference height-field seabed";
  const ReferenceResult flat = traceSeabedCaustics(FlatSurface(), desc);
  const glm::dvec3 t = refractSunRay(desc.towardSun, 0.0, 0.0, desc.ior);
  double worst = 0.0, spread = 0.0;
  for (size_t i = 0; i < flat.receivers[0].irradiance.size(); ++i) {
    // Bin means of D_x and D_z: differences of D across the bin, averaged along the other axis.
    const double b = desc.bins.binSize;
    const double x0 = desc.bins.origin.x + b * static_cast<double>(i % 12);
    const double z0 = desc.bins.origin.y + b * static_cast<double>(i / 12);
    double dx = 0.0, dz = 0.0;
    const int q = 200;
    for (int k = 0; k < q; ++k) {
      const double s = (k + 0.5) / q * b;
      dx += (depthAt(x0 + b, z0 + s) - depthAt(x0, z0 + s)) / b / q;
      dz += (depthAt(x0 + s, z0 + b) - depthAt(x0 + s, z0)) / b / q;
    }
    const double expected = 1.0 + (t.x * dx + t.z * dz) / t.y;
    spread = std::max(spread, std::abs(expected - 1.0));
    const double dev = std::abs(flat.receivers[0].irradiance[i] - expected);
    worst = std::max(worst, dev / flat.receivers[0].relativeError[i]);
    EXPECT_LE(dev, 3.0 * flat.receivers[0].relativeError[i]) << "bin " << i;
  }
  std::printf(
      "bumpy seabed under flat water: expected bins deviate from 1 by up to %.3f; worst "
      "|E - expected| = %.2f stated errors (median stated error %.3f %%)\n",
      spread, worst, 100.0 * flat.receivers[0].medianRelativeError);

  const SineSurface waves(0.05, 1.7);
  Receiver constant;
  constant.depth = 5.0;
  constant.minDepth = 5.0;
  constant.depthAt = [](double, double) { return 5.0; };
  desc.receivers = {Receiver::flat(5.0), constant};
  desc.maxRays = 1;  // one batch is enough to compare ray for ray
  const ReferenceResult both = traceSeabedCaustics(waves, desc);
  double maxDiff = 0.0;
  for (size_t i = 0; i < both.receivers[0].irradiance.size(); ++i)
    maxDiff = std::max(maxDiff,
                       std::abs(both.receivers[0].irradiance[i] - both.receivers[1].irradiance[i]));
  std::printf("constant height field vs flat receiver: max bin difference %.2e\n", maxDiff);
  EXPECT_LT(maxDiff, 1e-9);
}

TEST(SeabedReference, DeterministicAcrossRuns) {
  ReferenceDesc desc = quietDesc();
  desc.towardSun = glm::normalize(glm::dvec3(0.2, 1.0, 0.3));
  desc.bins = {{0.0, 0.0}, 0.2, 0.0, 8, 8};
  desc.receivers = {Receiver::flat(3.0)};
  desc.maxRays = 1;
  desc.progress = false;
  const SineSurface waves(0.08, 1.3);
  const ReferenceResult a = traceSeabedCaustics(waves, desc);
  desc.threads = 1;
  const ReferenceResult b = traceSeabedCaustics(waves, desc);
  ASSERT_EQ(a.receivers[0].irradiance.size(), b.receivers[0].irradiance.size());
  for (size_t i = 0; i < a.receivers[0].irradiance.size(); ++i)
    EXPECT_EQ(a.receivers[0].hits[i], b.receivers[0].hits[i]) << i;
}

}  // namespace
