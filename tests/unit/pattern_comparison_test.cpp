// compare's pattern metrics (sample_app/reference/pattern_comparison.h) on patterns with known
// answers: a pattern against itself, against a copy under a different albedo and shadow (which
// the flat-water division removes), against unrelated noise, against a blurred copy (too soft)
// and a copy with a ring added (a narrow peak).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include <pattern_comparison.h>

namespace {

using ocean::reference::comparePatterns;
using ocean::reference::PatternComparison;

constexpr int kW = 192, kH = 160;

// A caustic-like pattern (sharp bright lines over a floor of ~0.6), 1 on average.
std::vector<double> causticPattern(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 6.2831853);
  std::vector<double> p(size_t(kW) * kH, 0.0);
  double phases[6], angles[6];
  for (int i = 0; i < 6; ++i) phases[i] = u(rng), angles[i] = u(rng);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double s = 0.0;
      for (int i = 0; i < 6; ++i)
        s += std::cos((x * std::cos(angles[i]) + y * std::sin(angles[i])) * 0.45 + phases[i]);
      p[size_t(y) * kW + x] = 0.6 + 0.4 * std::exp(0.8 * s) / 6.0;
    }
  return p;
}

std::vector<double> boxBlur(const std::vector<double>& p, int r) {
  std::vector<double> out(p.size(), 0.0);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      double s = 0.0;
      int n = 0;
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx) {
          const int xx = std::clamp(x + dx, 0, kW - 1), yy = std::clamp(y + dy, 0, kH - 1);
          s += p[size_t(yy) * kW + xx];
          ++n;
        }
      out[size_t(y) * kW + x] = s / n;
    }
  return out;
}

// Added light of a frame whose pattern is `pattern` over the flat water light `flat`.
std::vector<double> times(const std::vector<double>& pattern, const std::vector<double>& flat) {
  std::vector<double> out(pattern.size());
  for (size_t i = 0; i < out.size(); ++i) out[i] = pattern[i] * flat[i];
  return out;
}

struct Frame {
  std::vector<double> flat = std::vector<double>(size_t(kW) * kH);
  std::vector<std::uint8_t> mask = std::vector<std::uint8_t>(size_t(kW) * kH, 1);
  Frame() {
    // Albedo, N.L and a soft shadow: what both sides share.
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x)
        flat[size_t(y) * kW + x] = (0.3 + 0.7 * ((x / 16 + y / 16) % 2)) *
                                   (x < kW / 3 ? 0.35 : 1.0) * (1.0 + 0.5 * y / kH);
  }
};

TEST(PatternComparison, APatternAgainstItselfAgreesPerfectly) {
  Frame f;
  const std::vector<double> added = times(causticPattern(1), f.flat);
  const PatternComparison c = comparePatterns(added, added, f.flat, f.mask, kW, kH);
  EXPECT_GT(c.pixels, size_t(kW * kH / 2));
  EXPECT_NEAR(c.correlation, 1.0, 1e-12);
  EXPECT_NEAR(c.relativeRmse, 0.0, 1e-12);
  EXPECT_NEAR(c.methodContrast, c.referenceContrast, 1e-12);
  EXPECT_EQ(c.spectrum.verdict, "as sharp");
  EXPECT_NEAR(c.spectrum.fineRatio, 1.0, 1e-9);
}

TEST(PatternComparison, WhatBothSidesShareDoesNotLiftThePatternsCorrelation) {
  Frame f;
  const std::vector<double> method = times(causticPattern(1), f.flat);
  const std::vector<double> reference = times(causticPattern(2), f.flat);
  // The whole added light correlates through the shared albedo and shadow ...
  double ma = 0, ra = 0, mm = 0, rr = 0, mr = 0;
  const double n = double(method.size());
  for (size_t i = 0; i < method.size(); ++i) ma += method[i] / n, ra += reference[i] / n;
  for (size_t i = 0; i < method.size(); ++i) {
    mm += (method[i] - ma) * (method[i] - ma);
    rr += (reference[i] - ra) * (reference[i] - ra);
    mr += (method[i] - ma) * (reference[i] - ra);
  }
  const double wholeFrame = mr / std::sqrt(mm * rr);
  // ... the patterns do not.
  const PatternComparison c = comparePatterns(method, reference, f.flat, f.mask, kW, kH);
  std::printf("unrelated patterns: whole frame %.3f, pattern %.3f\n", wholeFrame, c.correlation);
  EXPECT_GT(wholeFrame, 0.5);
  EXPECT_LT(std::abs(c.correlation), 0.2);
}

TEST(PatternComparison, ABlurredPatternIsTooSoftAndKeepsItsMean) {
  Frame f;
  const std::vector<double> pattern = causticPattern(3);
  const std::vector<double> blurred = boxBlur(pattern, 3);
  const PatternComparison c =
      comparePatterns(times(blurred, f.flat), times(pattern, f.flat), f.flat, f.mask, kW, kH);
  EXPECT_EQ(c.spectrum.verdict, "too soft") << c.spectrum.fineRatio;
  EXPECT_LT(c.methodContrast, c.referenceContrast);
  EXPECT_NEAR(c.methodMean / c.referenceMean, 1.0, 0.02);
  // And the other way round.
  const PatternComparison r =
      comparePatterns(times(pattern, f.flat), times(blurred, f.flat), f.flat, f.mask, kW, kH);
  EXPECT_EQ(r.spectrum.verdict, "too sharp") << r.spectrum.fineRatio;
}

TEST(PatternComparison, ARingTheTraceLacksIsANarrowPeak) {
  Frame f;
  const std::vector<double> pattern = boxBlur(causticPattern(4), 2);
  std::vector<double> ringed = pattern;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double r = std::hypot(x - kW / 2.0, y - kH / 2.0);
      ringed[size_t(y) * kW + x] += 0.15 * std::cos(6.2831853 * r / 10.0);  // 10-pixel rings
    }
  const PatternComparison clean =
      comparePatterns(times(pattern, f.flat), times(pattern, f.flat), f.flat, f.mask, kW, kH);
  const PatternComparison c =
      comparePatterns(times(ringed, f.flat), times(pattern, f.flat), f.flat, f.mask, kW, kH);
  std::printf("peak %.2f at %.1f px (clean %.2f)\n", c.spectrum.peak, c.spectrum.peakPeriodPixels,
              clean.spectrum.peak);
  EXPECT_NEAR(clean.spectrum.peak, 1.0, 1e-9);
  EXPECT_GT(c.spectrum.peak, 1.5);
  EXPECT_NEAR(c.spectrum.peakPeriodPixels, 10.0, 3.0);
}

TEST(PatternComparison, DarkFlatPixelsAndTheMaskAreLeftOut) {
  Frame f;
  for (int x = 0; x < kW; ++x) f.flat[x] = 0.0;  // a top row flat water leaves dark
  for (int y = kH / 2; y < kH; ++y)
    for (int x = 0; x < kW; ++x) f.mask[size_t(y) * kW + x] = 0;
  const std::vector<double> added = times(causticPattern(5), f.flat);
  const PatternComparison c = comparePatterns(added, added, f.flat, f.mask, kW, kH);
  for (int x = 0; x < kW; ++x) EXPECT_EQ(c.compared[size_t(x)], 0);
  for (size_t i = size_t(kH / 2) * kW; i < c.compared.size(); ++i) ASSERT_EQ(c.compared[i], 0);
  EXPECT_LE(c.pixels, size_t(kW) * (kH / 2 - 1));
  EXPECT_TRUE(std::isfinite(c.correlation));
}

}  // namespace
