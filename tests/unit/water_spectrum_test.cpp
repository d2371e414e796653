// The spectrum math: input validation, JONSWAP and spreading normalisation, cascade bands,
// determinism, time quantisation, and the mean-square slope the grid reproduces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <postfx/water/initial_spectrum.h>
#include <postfx/water/random.h>
#include <postfx/water/spectrum.h>

namespace {

using postfx::water::OceanDesc;
using postfx::water::Result;

constexpr double kPi = std::numbers::pi;

Result validate(const OceanDesc& desc) {
  std::string error;
  const Result result = postfx::water::validateOceanDesc(desc, error);
  if (result != Result::Ok) {
    EXPECT_FALSE(error.empty());
  }
  return result;
}

TEST(WaterDesc, DefaultsAreValid) {
  EXPECT_EQ(validate(OceanDesc{}), Result::Ok);
}

TEST(WaterDesc, RejectsBadResolution) {
  for (int n : {0, -64, 3, 100, 4, 1024}) {
    OceanDesc desc;
    desc.resolution = n;
    EXPECT_EQ(validate(desc), Result::InvalidArgument) << n;
  }
}

TEST(WaterDesc, RejectsNonFiniteAndOutOfRangeFields) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto expectRejected = [](auto edit) {
    OceanDesc desc;
    edit(desc);
    EXPECT_EQ(validate(desc), Result::InvalidArgument);
  };
  expectRejected([&](OceanDesc& d) { d.windSpeed = nan; });
  expectRejected([&](OceanDesc& d) { d.windSpeed = -1.0; });
  expectRejected([&](OceanDesc& d) { d.windSpeed = inf; });
  expectRejected([&](OceanDesc& d) { d.windDirection = nan; });
  expectRejected([&](OceanDesc& d) { d.fetch = 0.0; });
  expectRejected([&](OceanDesc& d) { d.peakEnhancement = 0.5; });
  expectRejected([&](OceanDesc& d) { d.spreading = nan; });
  expectRejected([&](OceanDesc& d) { d.choppiness = -0.1; });
  expectRejected([&](OceanDesc& d) { d.depth = -1.0; });
  expectRejected([&](OceanDesc& d) { d.loopPeriod = 0.0; });
  expectRejected([&](OceanDesc& d) { d.cascadeCount = 0; });
  expectRejected([&](OceanDesc& d) { d.cascadeCount = 5; });
  expectRejected([&](OceanDesc& d) { d.tileSize[1] = d.tileSize[0]; });
  expectRejected([&](OceanDesc& d) { d.tileSize[2] = nan; });
  expectRejected([&](OceanDesc& d) {
    d.resolution = 8;  // 250 / 37 is above 8 / 2: the bands could not hand over
  });
}

TEST(WaterSpectrum, JonswapPeaksAtTheFetchLimitedPeakFrequency) {
  OceanDesc desc;
  const double peak = 22.0 * std::cbrt(postfx::water::kGravity * postfx::water::kGravity /
                                       (desc.windSpeed * desc.fetch));
  double best = 0.0, bestOmega = 0.0;
  for (double omega = 0.1; omega < 5.0; omega += 1e-4) {
    const double s = postfx::water::jonswap(omega, desc);
    ASSERT_TRUE(std::isfinite(s));
    if (s > best) best = s, bestOmega = omega;
  }
  EXPECT_NEAR(bestOmega, peak, 0.01 * peak);
}

TEST(WaterSpectrum, SpreadingIntegratesToOne) {
  for (double s : {0.0, 1.0, 8.0, 200.0}) {
    double sum = 0.0;
    const int steps = 200000;
    for (int i = 0; i < steps; ++i) {
      sum += postfx::water::directionalSpreading(-kPi + (i + 0.5) * 2.0 * kPi / steps, s);
    }
    EXPECT_NEAR(sum * 2.0 * kPi / steps, 1.0, 1e-6) << "s = " << s;
  }
}

TEST(WaterSpectrum, ShallowDispersionTendsToDeepWater) {
  EXPECT_NEAR(postfx::water::dispersion(1.0, 1000.0), postfx::water::dispersion(1.0, 0.0), 1e-12);
  // Shallow limit: omega = k sqrt(g d).
  EXPECT_NEAR(postfx::water::dispersion(1e-3, 1.0), 1e-3 * std::sqrt(postfx::water::kGravity),
              1e-8);
}

TEST(WaterSpectrum, CascadeBandsAreContiguousAndDisjoint) {
  OceanDesc desc;
  const auto bands = postfx::water::cascadeBands(desc);
  ASSERT_EQ(bands.size(), 3u);
  EXPECT_EQ(bands[0].kMin, 0.0);
  for (size_t c = 0; c + 1 < bands.size(); ++c) {
    EXPECT_EQ(bands[c].kMax, bands[c + 1].kMin);
    EXPECT_LT(bands[c].kMin, bands[c].kMax);
    // The finer grid resolves its lower edge, the coarser grid its upper edge.
    EXPECT_GT(bands[c].kMax, 2.0 * kPi / desc.tileSize[c + 1]);
    EXPECT_LE(bands[c].kMax, kPi * desc.resolution / desc.tileSize[c]);
  }
}

// Every nonzero mode lies inside its cascade's band: nothing is counted by two cascades.
TEST(WaterSpectrum, ModesStayInsideTheirBand) {
  OceanDesc desc;
  desc.resolution = 64;
  const auto spectrum = postfx::water::buildInitialSpectrum(desc);
  const auto bands = postfx::water::cascadeBands(desc);
  const int n = desc.resolution;
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const double dk = 2.0 * kPi / desc.tileSize[c];
    int nonzero = 0;
    for (int m = 0; m < n; ++m) {
      for (int i = 0; i < n; ++i) {
        const size_t at = spectrum.index(c, i, m);
        if (spectrum.a[at] == std::complex<double>{}) continue;
        ++nonzero;
        const double k = std::hypot(postfx::water::signedFrequency(i, n) * dk,
                                    postfx::water::signedFrequency(m, n) * dk);
        EXPECT_GE(k, bands[c].kMin);
        EXPECT_LT(k, bands[c].kMax);
      }
    }
    EXPECT_GT(nonzero, 100) << "cascade " << c;
  }
}

TEST(WaterSpectrum, InitialSpectrumIsBitIdenticalAcrossBuilds) {
  OceanDesc desc;
  desc.resolution = 32;
  const auto first = postfx::water::buildInitialSpectrum(desc);
  const auto second = postfx::water::buildInitialSpectrum(desc);
  EXPECT_EQ(first.a, second.a);
  EXPECT_EQ(first.b, second.b);
  EXPECT_EQ(first.cycles, second.cycles);
  desc.seed += 1;
  EXPECT_NE(postfx::water::buildInitialSpectrum(desc).a, first.a);
}

TEST(WaterSpectrum, RandomSourceIsStandardNormal) {
  postfx::water::GaussianRandom random(42);
  double sum = 0.0, sum2 = 0.0;
  const int pairs = 200000;
  for (int i = 0; i < pairs; ++i) {
    double x = 0.0, y = 0.0;
    random.nextPair(x, y);
    sum += x + y;
    sum2 += x * x + y * y;
  }
  const double count = 2.0 * pairs;
  EXPECT_NEAR(sum / count, 0.0, 0.01);
  EXPECT_NEAR(sum2 / count, 1.0, 0.01);
}

TEST(WaterSpectrum, FrequenciesAreWholeCyclesPerLoop) {
  OceanDesc desc;
  desc.resolution = 16;
  const auto spectrum = postfx::water::buildInitialSpectrum(desc);
  const int n = desc.resolution;
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const double dk = 2.0 * kPi / desc.tileSize[c];
    for (int m = 0; m < n; ++m) {
      for (int i = 0; i < n; ++i) {
        const double k = std::hypot(postfx::water::signedFrequency(i, n) * dk,
                                    postfx::water::signedFrequency(m, n) * dk);
        const double exact = postfx::water::dispersion(k, 0.0) * desc.loopPeriod / (2.0 * kPi);
        EXPECT_LE(std::abs(spectrum.cycles[spectrum.index(c, i, m)] - exact), 0.5);
      }
    }
  }
}

TEST(WaterSpectrum, LoopPhaseIsPeriodicAndExactFarFromZero) {
  const double period = 600.0;
  EXPECT_EQ(postfx::water::loopPhase(0.0, period), 0u);
  EXPECT_EQ(postfx::water::loopPhase(period, period), 0u);
  EXPECT_EQ(postfx::water::loopPhase(150.0, period), 1u << 30);
  EXPECT_EQ(postfx::water::loopPhase(-150.0, period), 3u << 30);
  // 1e7 = 16666 * 600 + 400: the state at 1e7 s is exactly the one at 400 s.
  EXPECT_EQ(postfx::water::loopPhase(1e7, period), postfx::water::loopPhase(400.0, period));
  EXPECT_EQ(postfx::water::loopPhase(1e7 + 0.25, period), postfx::water::loopPhase(400.25, period));
}

TEST(WaterSpectrum, CalmSeaHasNoEnergyAndNoNaN) {
  OceanDesc desc;
  desc.windSpeed = 0.0;
  desc.resolution = 16;
  const auto spectrum = postfx::water::buildInitialSpectrum(desc);
  for (size_t i = 0; i < spectrum.a.size(); ++i) {
    ASSERT_EQ(spectrum.a[i], std::complex<double>{});
    ASSERT_EQ(spectrum.b[i], std::complex<double>{});
  }
  EXPECT_EQ(postfx::water::discreteMeanSquareSlope(desc), 0.0);
}

// Physics: the cascaded grid reproduces the continuous spectrum's mean-square slope. The grid
// misses only the lowest wavenumbers near the first cascade's fundamental, where k^2 S(k) is
// small; 3 % covers that discretisation.
TEST(WaterSpectrum, GridReproducesTheContinuousMeanSquareSlope) {
  for (double wind : {5.0, 10.0, 20.0}) {
    OceanDesc desc;
    desc.resolution = 128;
    desc.windSpeed = wind;
    const double discrete = postfx::water::discreteMeanSquareSlope(desc);
    const double integral = postfx::water::integratedMeanSquareSlope(desc);
    std::cout << "wind " << wind << " m/s: mean-square slope grid " << discrete << ", integral "
              << integral << ", ratio " << discrete / integral << "\n";
    EXPECT_NEAR(discrete / integral, 1.0, 0.03) << "wind " << wind;
  }
}

}  // namespace

// The per-cascade statistics the caustics use to leave out waves that cannot focus: checked
// against an independent integral of the continuous spectrum over each cascade's band.
TEST(WaterSpectrum, CascadeWaveStatsMatchTheSpectrumIntegrals) {
  const postfx::water::OceanDesc desc;
  const std::vector<postfx::water::CascadeBand> bands = postfx::water::cascadeBands(desc);
  const std::vector<postfx::water::CascadeWaveStats> stats = postfx::water::cascadeWaveStats(desc);
  ASSERT_EQ(stats.size(), bands.size());
  for (size_t c = 0; c < stats.size(); ++c) {
    // Simpson in log k of k^p S_iso(k) k dk over the band, S_iso = S(omega) omega' / k.
    auto moment = [&](int power) {
      const double lo = std::log(std::max(bands[c].kMin, 1e-5)), hi = std::log(bands[c].kMax);
      const int steps = 20000;
      const double h = (hi - lo) / steps;
      double sum = 0.0;
      for (int i = 0; i <= steps; ++i) {
        const double k = std::exp(lo + i * h);
        const double f = std::pow(k, power) *
                         postfx::water::jonswap(postfx::water::dispersion(k, 0.0), desc) *
                         postfx::water::dispersionDerivative(k, 0.0) * k;
        sum += (i == 0 || i == steps ? 1.0 : (i % 2 ? 4.0 : 2.0)) * f;
      }
      return sum * h / 3.0;
    };
    const double slope = std::sqrt(moment(2)), laplacian = std::sqrt(moment(4));
    std::printf(
        "cascade %zu: rms slope %.4f (integral %.4f), rms laplacian %.4f /m (integral "
        "%.4f), first-order focus at %.1f m, longest wave %.2f m\n",
        c, stats[c].rmsSlope, slope, stats[c].rmsLaplacian, laplacian,
        1.0 / ((1.0 - 1.0 / 1.333) * stats[c].rmsLaplacian), stats[c].longestWavelength);
    // The FFT's square grid holds the band's annulus only approximately (corners, the coarse
    // modes near kMin): within 2 % (0.5 % measured).
    EXPECT_NEAR(stats[c].rmsSlope / slope, 1.0, 0.02) << c;
    EXPECT_NEAR(stats[c].rmsLaplacian / laplacian, 1.0, 0.02) << c;
    const double fundamental = 2.0 * std::numbers::pi / desc.tileSize[c];
    EXPECT_DOUBLE_EQ(stats[c].longestWavelength,
                     2.0 * std::numbers::pi / std::max(bands[c].kMin, fundamental));
    if (c > 0) {
      EXPECT_GT(stats[c].rmsLaplacian, stats[c - 1].rmsLaplacian);
    }
  }
  postfx::water::OceanDesc calm;
  calm.windSpeed = 0.0;
  for (const postfx::water::CascadeWaveStats& s : postfx::water::cascadeWaveStats(calm)) {
    EXPECT_EQ(s.rmsSlope, 0.0);
    EXPECT_EQ(s.rmsLaplacian, 0.0);
  }
}
