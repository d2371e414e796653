// The GPU ocean against its double-precision CPU reference, the texture contract, and time:
// periodicity, far-from-zero times and the physics of the slope statistics.
#include <gl_fixture.h>

#include <cmath>
#include <cstring>
#include <iostream>
#include <numbers>
#include <sstream>

#include <postfx/water/initial_spectrum.h>
#include <postfx/water/reference.h>
#include <postfx/water/spectrum.h>

#include "water_test_util.h"

namespace {

using testsupport::GlTest;
using watertest::readDisplacement;
using watertest::readSlope;

std::unique_ptr<postfx::water::Ocean> makeOcean(const postfx::water::OceanDesc& desc) {
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  const postfx::water::Result result = postfx::water::Ocean::create(desc, ocean, error);
  EXPECT_EQ(result, postfx::water::Result::Ok) << error;
  return ocean;
}

class WaterOcean : public GlTest {};

// fp16 keeps 11 significant bits, so one unit in the last place is at most 2^-10 |v|; we allow a
// whole ulp because llvmpipe's imageStore truncates toward zero instead of rounding (measured:
// every worst-case texel is the fp16 value just below the reference). The fp32 FFT and sin/cos
// add ~1e-6 of the field's RMS; 2e-4 RMS leaves room for drivers with coarser sin/cos. A bug in
// the GPU path (sign, texel offset, phase) shows up at the 10-100 % level instead.
TEST_F(WaterOcean, MatchesCpuReferenceWithinHalfPrecision) {
  const postfx::water::OceanDesc desc = watertest::smallDesc();
  auto ocean = makeOcean(desc);
  ASSERT_TRUE(ocean);
  const postfx::water::InitialSpectrum spectrum = postfx::water::buildInitialSpectrum(desc);
  const int n = desc.resolution;
  const size_t perLayer = static_cast<size_t>(n) * n;
  double maxSlopeError = 0.0, maxHeightError = 0.0, maxJacobianError = 0.0, maxDispError = 0.0;
  for (double time : {0.0, 17.25, 431.9}) {
    ASSERT_EQ(ocean->update(time), postfx::water::Result::Ok);
    const auto slope = readSlope(*ocean);
    const auto displacement = readDisplacement(*ocean);
    for (int c = 0; c < desc.cascadeCount; ++c) {
      const auto reference = postfx::water::evaluateReference(spectrum, desc, c, time);
      glm::dvec4 rms(0.0), rmsDisp(0.0);
      for (size_t t = 0; t < perLayer; ++t) {
        rms += reference.slope[t] * reference.slope[t];
        rmsDisp += reference.displacement[t] * reference.displacement[t];
      }
      rms = glm::sqrt(rms / double(perLayer));
      rmsDisp = glm::sqrt(rmsDisp / double(perLayer));
      for (size_t t = 0; t < perLayer; ++t) {
        const glm::dvec4 gpu = glm::dvec4(slope[c * perLayer + t]);
        const glm::dvec4 cpu = reference.slope[t];
        const glm::dvec4 error = glm::abs(gpu - cpu);
        const glm::dvec4 bound = glm::abs(cpu) * 0x1.0p-10 + rms * 2e-4 + 1e-7;
        const glm::dvec4 gpuDisp = glm::dvec4(displacement[c * perLayer + t]);
        const glm::dvec4 errorDisp = glm::abs(gpuDisp - reference.displacement[t]);
        const glm::dvec4 boundDisp =
            glm::abs(reference.displacement[t]) * 0x1.0p-10 + rmsDisp * 2e-4 + 1e-7;
        for (int k = 0; k < 4; ++k) {
          ASSERT_LE(error[k], bound[k])
              << "slope component " << k << " cascade " << c << " texel " << t << " time " << time;
          ASSERT_LE(errorDisp[k], boundDisp[k]) << "displacement component " << k;
        }
        maxSlopeError = std::max({maxSlopeError, error.x, error.y});
        maxHeightError = std::max(maxHeightError, error.z);
        maxJacobianError = std::max(maxJacobianError, error.w);
        maxDispError = std::max({maxDispError, errorDisp.x, errorDisp.z});
      }
    }
  }
  std::cout << "GPU vs CPU (N = " << n << ", " << desc.cascadeCount
            << " cascades, 3 times): max |error| slope " << maxSlopeError << ", height "
            << maxHeightError << " m, Jacobian " << maxJacobianError << ", displacement "
            << maxDispError << " m\n";
  RecordProperty("max_slope_error", std::to_string(maxSlopeError));
  RecordProperty("max_height_error_m", std::to_string(maxHeightError));
  RecordProperty("max_jacobian_error", std::to_string(maxJacobianError));
}

TEST_F(WaterOcean, TexturesFollowTheContract) {
  auto ocean = makeOcean(watertest::smallDesc());
  ASSERT_TRUE(ocean);
  for (GLuint texture : {ocean->slopeTexture(), ocean->displacementTexture()}) {
    GLint format = 0, levels = 0, minFilter = 0, wrapS = 0, wrapT = 0, depth = 0;
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_DEPTH, &depth);
    glGetTextureParameteriv(texture, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
    glGetTextureParameteriv(texture, GL_TEXTURE_MIN_FILTER, &minFilter);
    glGetTextureParameteriv(texture, GL_TEXTURE_WRAP_S, &wrapS);
    glGetTextureParameteriv(texture, GL_TEXTURE_WRAP_T, &wrapT);
    EXPECT_EQ(format, GL_RGBA16F);
    EXPECT_EQ(depth, 3);
    EXPECT_EQ(levels, 7);  // 64 .. 1
    EXPECT_EQ(minFilter, GL_LINEAR_MIPMAP_LINEAR);
    EXPECT_EQ(wrapS, GL_REPEAT);
    EXPECT_EQ(wrapT, GL_REPEAT);
  }
  char label[64] = {};
  glGetObjectLabel(GL_TEXTURE, ocean->slopeTexture(), sizeof(label), nullptr, label);
  EXPECT_STREQ(label, "water.slope");
  // The mips are regenerated every update: the 1x1 level is the mean of level 0.
  ASSERT_EQ(ocean->update(55.5), postfx::water::Result::Ok);
  const auto level0 = readSlope(*ocean);
  const auto top = watertest::readLevel(ocean->slopeTexture(), 6, 1, 3);
  for (int c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (size_t t = 0; t < 64 * 64; ++t) mean += static_cast<double>(level0[c * 64 * 64 + t].z);
    mean /= 64.0 * 64.0;
    EXPECT_NEAR(top[c].z, mean, 1e-3) << "cascade " << c;
    EXPECT_NEAR(top[c].w, 1.0, 0.05) << "mean Jacobian";
  }
  // Displacement's height channel is the slope texture's height channel.
  const auto displacement = readDisplacement(*ocean);
  for (size_t t = 0; t < level0.size(); ++t) ASSERT_EQ(displacement[t].y, level0[t].z);
}

TEST_F(WaterOcean, RepeatsAfterTheLoopPeriod) {
  const postfx::water::OceanDesc desc = watertest::smallDesc();
  auto ocean = makeOcean(desc);
  ASSERT_TRUE(ocean);
  const double time = 73.3;
  ASSERT_EQ(ocean->update(time), postfx::water::Result::Ok);
  const auto first = readSlope(*ocean);
  ASSERT_EQ(ocean->update(time + desc.loopPeriod), postfx::water::Result::Ok);
  const auto second = readSlope(*ocean);
  double maxDifference = 0.0, maxValue = 0.0;
  for (size_t t = 0; t < first.size(); ++t) {
    const glm::vec4 d = glm::abs(first[t] - second[t]);
    maxDifference = std::max({maxDifference, double(d.x), double(d.y), double(d.z)});
    maxValue = std::max({maxValue, double(std::abs(first[t].z))});
  }
  std::cout << "t vs t + T: max |difference| " << maxDifference << " (max |h| " << maxValue
            << ")\n";
  // t + T rounds to the same 2^-32 loop phase or its neighbour (~1e-7 s): identical in fp16.
  EXPECT_LE(maxDifference, 1e-3 * maxValue);
}

// At t = 1e7 s a float phase w * t would be off by whole radians; the integer loop phase makes
// it bit-identical to t mod T.
TEST_F(WaterOcean, FarFutureTimeIsAsCleanAsLoopStart) {
  const postfx::water::OceanDesc desc = watertest::smallDesc();
  auto ocean = makeOcean(desc);
  ASSERT_TRUE(ocean);
  ASSERT_EQ(ocean->update(1e7), postfx::water::Result::Ok);
  const auto far = readSlope(*ocean);
  ASSERT_EQ(ocean->update(std::fmod(1e7, desc.loopPeriod)), postfx::water::Result::Ok);
  const auto reduced = readSlope(*ocean);
  ASSERT_EQ(ocean->update(0.0), postfx::water::Result::Ok);
  const auto start = readSlope(*ocean);
  EXPECT_TRUE(watertest::allFinite(far));
  EXPECT_EQ(0, std::memcmp(far.data(), reduced.data(), far.size() * sizeof(glm::vec4)));
  const double farSlope = watertest::meanSquareSlope(far, desc.resolution, desc.cascadeCount);
  const double startSlope = watertest::meanSquareSlope(start, desc.resolution, desc.cascadeCount);
  std::cout << "mean-square slope t = 0: " << startSlope << ", t = 1e7 s: " << farSlope << "\n";
  EXPECT_NEAR(farSlope / startSlope, 1.0, 0.01);
}

// Physics: the slope variance of the rendered sea is the spectrum's sum of k^2 S(k) dk^2. One
// realisation fluctuates around it: each mode's power is exponentially distributed, so the
// relative standard deviation is sqrt(sum w^2) / sum w with w = k^2 S(k) dk^2, times ~sqrt(2) for
// the a-b cross terms at one instant. Slope is dominated by the few modes around the spectral
// peak, so one sea is ~10 % off; we average 8 seeds x 6 times and allow 3 sigma / sqrt(8) + 1 %.
TEST_F(WaterOcean, SlopeVarianceMatchesTheSpectrum) {
  postfx::water::OceanDesc desc = watertest::smallDesc(64);
  const int seeds = 8;
  const double times[] = {0.0, 41.0, 97.5, 173.1, 260.0, 517.3};
  double measured = 0.0;
  for (int seed = 0; seed < seeds; ++seed) {
    desc.seed = 1000u + static_cast<uint64_t>(seed);
    auto ocean = makeOcean(desc);
    ASSERT_TRUE(ocean);
    for (double time : times) {
      ASSERT_EQ(ocean->update(time), postfx::water::Result::Ok);
      measured += watertest::meanSquareSlope(readSlope(*ocean), desc.resolution, desc.cascadeCount);
    }
  }
  measured /= seeds * static_cast<double>(std::size(times));
  const double expected = postfx::water::discreteMeanSquareSlope(desc);
  const auto bands = postfx::water::cascadeBands(desc);
  const int n = desc.resolution;
  double sumW = 0.0, sumW2 = 0.0;
  for (int c = 0; c < desc.cascadeCount; ++c) {
    const double dk = 2.0 * std::numbers::pi / desc.tileSize[c];
    for (int m = 0; m < n; ++m) {
      for (int i = 0; i < n; ++i) {
        const double kx = postfx::water::signedFrequency(i, n) * dk;
        const double kz = postfx::water::signedFrequency(m, n) * dk;
        const double k = std::hypot(kx, kz);
        if (i == n / 2 || m == n / 2 || k == 0.0 || k < bands[c].kMin || k >= bands[c].kMax) {
          continue;
        }
        const double w = k * k * postfx::water::waveSpectrum(kx, kz, desc) * dk * dk;
        sumW += w;
        sumW2 += w * w;
      }
    }
  }
  const double sigma = std::sqrt(2.0 * sumW2) / sumW / std::sqrt(double(seeds));
  std::cout << "mean-square slope (" << seeds << " seeds): measured " << measured
            << ", spectrum sum " << expected << ", continuous integral "
            << postfx::water::integratedMeanSquareSlope(desc) << ", ratio " << measured / expected
            << ", sigma of the mean " << sigma << "\n";
  RecordProperty("mean_square_slope_ratio", std::to_string(measured / expected));
  EXPECT_NEAR(measured / expected, 1.0, 3.0 * sigma + 0.01);
}

}  // namespace
