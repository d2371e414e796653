// The compare step's metrics (sample_app/reference/caustic_comparison.h): identical inputs
// correlate perfectly with no error, a shuffled image does not correlate, the mask decides which
// pixels count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "caustic_comparison.h"

namespace {

using ocean::reference::CausticComparison;
using ocean::reference::compareAddedLight;

// A caustic-like pattern: a network of bright lines over a dim floor, 200 x 100 pixels.
std::vector<double> pattern() {
  std::vector<double> v(200 * 100);
  for (int y = 0; y < 100; ++y)
    for (int x = 0; x < 200; ++x) {
      const double a = std::sin(0.31 * x + 0.7 * std::sin(0.13 * y)) *
                       std::sin(0.23 * y + 0.5 * std::cos(0.11 * x));
      v[static_cast<size_t>(y) * 200 + x] = 0.2 + std::pow(std::abs(a), 8.0) * 3.0;
    }
  return v;
}

TEST(CausticComparison, IdenticalInputsCorrelateOneWithNoError) {
  const std::vector<double> r = pattern();
  const CausticComparison c = compareAddedLight(r, r, std::vector<std::uint8_t>(r.size(), 1));
  EXPECT_EQ(c.pixels, r.size());
  EXPECT_NEAR(c.correlation, 1.0, 1e-12);
  EXPECT_EQ(c.relativeRmse, 0.0);
}

TEST(CausticComparison, AShuffledImageDoesNotCorrelate) {
  const std::vector<double> r = pattern();
  std::vector<double> shuffled = r;
  std::mt19937_64 random(7);
  std::shuffle(shuffled.begin(), shuffled.end(), random);
  const CausticComparison c =
      compareAddedLight(shuffled, r, std::vector<std::uint8_t>(r.size(), 1));
  // The correlation of independent samples scatters by 1/sqrt(20000) = 0.007.
  EXPECT_LT(std::abs(c.correlation), 0.03);
  // Same values, so the same mean and variance: the error is sqrt(2 var / E[r^2]).
  EXPECT_GT(c.relativeRmse, 0.5);
}

TEST(CausticComparison, ScaleShowsInTheErrorNotInTheCorrelation) {
  const std::vector<double> r = pattern();
  std::vector<double> twice = r;
  for (double& v : twice) v *= 2.0;
  const CausticComparison c = compareAddedLight(twice, r, std::vector<std::uint8_t>(r.size(), 1));
  EXPECT_NEAR(c.correlation, 1.0, 1e-12);
  EXPECT_NEAR(c.relativeRmse, 1.0, 1e-12);
}

TEST(CausticComparison, OnlyMaskedPixelsCount) {
  std::vector<double> r = pattern(), m = r;
  std::vector<std::uint8_t> mask(r.size(), 1);
  for (size_t i = 0; i < r.size(); i += 3) {
    mask[i] = 0;
    m[i] = std::nan("");  // garbage outside the mask changes nothing
  }
  const CausticComparison c = compareAddedLight(m, r, mask);
  EXPECT_EQ(c.pixels, r.size() - (r.size() + 2) / 3);
  EXPECT_NEAR(c.correlation, 1.0, 1e-12);
  EXPECT_EQ(c.relativeRmse, 0.0);
}

}  // namespace
