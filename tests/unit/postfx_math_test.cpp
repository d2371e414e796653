// The shader's caustic math (shaders/shared/postfx_caustics.h) evaluated on the CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "frame_constants.h"
#include "shared_math.h"

namespace {

namespace sh = postfx::shared;
const float kNan = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

TEST(PostfxCausticMath, OmegaIsOneWhenAlignedWithNothingAndDecaysWithA) {
  const glm::vec3 reference(1, 0, 0);
  EXPECT_FLOAT_EQ(sh::causticOmega(glm::vec3(0, -1, 0), reference, 60.0f), 1.0f);
  const glm::vec3 tilted = glm::normalize(glm::vec3(0.1f, -1.0f, 0.0f));
  EXPECT_FLOAT_EQ(sh::causticOmega(tilted, reference, 60.0f),
                  std::exp(-60.0f * tilted.x * tilted.x));
  EXPECT_FLOAT_EQ(sh::causticOmega(tilted, reference, 0.0f), 1.0f) << "tau 0: uniform light";
  EXPECT_EQ(sh::causticOmega(glm::vec3(1, 0, 0), reference, 1e6f), 0.0f) << "underflow to 0";
}

TEST(PostfxCausticMath, FlatWaterGivesOmegaOneForAnySunAboveTheHorizon) {
  for (double elevation : {90.0, 45.0, 10.0, 0.01}) {
    const double e = glm::radians(elevation);
    const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
    const glm::vec3 reference(postfx::detail::incidencePlaneNormal(sun));
    const float omega =
        sh::causticFactor(glm::vec3(sun), glm::vec3(0, 1, 0), 1.0f / 1.333f, reference, 1e6f, 0.5f);
    EXPECT_NEAR(omega, 1.0f, 1e-5f) << elevation;
  }
}

TEST(PostfxCausticMath, FactorBoundedForAnyNormal) {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.01f, 0.2f));
  for (float sx = -70.0f; sx <= 70.0f; sx += 3.5f) {
    const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, -0.5f * sx));
    const float omega = sh::causticFactor(sun, n, 0.75f, glm::vec3(0, 0, 1), 30.0f, 0.3f);
    EXPECT_TRUE(omega >= 0.0f && omega <= 1.0f) << sx;
  }
}

// The factor is written with dot products only; it must equal the textbook form that builds the
// refracted and reflected rays with refract()/reflect() (GLSL's definitions, as glm's).
float factorFromRays(glm::vec3 sun, glm::vec3 n, float eta, glm::vec3 reference, float tau,
                     float reflectionWeight) {
  const glm::vec3 refracted = glm::refract(-sun, n, eta);
  const glm::vec3 reflected = glm::reflect(-sun, n);
  const float t = sh::causticOmega(refracted, reference, tau);
  const float r = sh::causticOmega(reflected, reference, tau);
  return t + (r - t) * reflectionWeight;
}

TEST(PostfxCausticMath, FactorFromDotProductsEqualsRefractAndReflect) {
  double worst = 0.0;
  int cases = 0;
  for (double elevation : {89.9, 60.0, 20.0, 3.0}) {
    const double e = glm::radians(elevation);
    const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
    const glm::vec3 reference(postfx::detail::incidencePlaneNormal(sun));
    // eta > 1 with steep normals reaches total internal reflection (refract() gives 0).
    for (float eta : {1.0f / 1.333f, 1.0f / 1.34f, 1.0f, 1.5f}) {
      for (float sx = -3.0f; sx <= 3.0f; sx += 0.37f) {
        for (float sz = -3.0f; sz <= 3.0f; sz += 0.41f) {
          const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, sz));
          for (float tau : {0.0f, 60.0f, 800.0f}) {
            const float expected = factorFromRays(glm::vec3(sun), n, eta, reference, tau, 0.25f);
            const float got = sh::causticFactor(glm::vec3(sun), n, eta, reference, tau, 0.25f);
            worst = std::max(worst, double(std::abs(got - expected)));
            ++cases;
          }
        }
      }
    }
  }
  std::printf("dot-product factor vs refract/reflect: worst |difference| %.3g over %d cases\n",
              worst, cases);
  // |d omega / da| = 2 tau a omega peaks at sqrt(2 tau / e) ~ 24 for tau 800, so float rounding
  // of the cosines (a few 1e-7) moves omega by under 1e-5.
  EXPECT_LT(worst, 1e-5);
}

TEST(PostfxCausticMath, DispersedFactorIsThePerChannelFactor) {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));
  const glm::vec3 reference(postfx::detail::incidencePlaneNormal(glm::dvec3(sun)));
  const glm::vec3 eta(1.0f / 1.331f, 1.0f / 1.337f, 1.0f / 1.343f);
  for (float sx = -1.0f; sx <= 1.0f; sx += 0.13f) {
    const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, 0.7f * sx));
    const glm::vec3 rgb = sh::causticFactorRgb(sun, n, eta, reference, 800.0f, 0.25f);
    for (int c = 0; c < 3; ++c)
      EXPECT_FLOAT_EQ(rgb[c], sh::causticFactor(sun, n, eta[c], reference, 800.0f, 0.25f)) << sx;
  }
}

TEST(PostfxCausticMath, BrokenSlopesBecomeFlatWater) {
  EXPECT_EQ(sh::waterNormalFromSlopes(glm::vec2(kNan, 0.0f)), glm::vec3(0, 1, 0));
  EXPECT_EQ(sh::waterNormalFromSlopes(glm::vec2(kInf, -kInf)), glm::vec3(0, 1, 0));
  EXPECT_EQ(sh::sanitizeSlopes(glm::vec2(0.5f, kNan)), glm::vec2(0.5f, 0.0f));
}

TEST(PostfxCausticMath, BeerLambertIsExactPerChannel) {
  const glm::vec3 sigma(0.4f, 0.07f, 0.02f);
  const glm::vec3 at4 = sh::causticTransmittance(sigma, 4.0f);
  const glm::vec3 at6 = sh::causticTransmittance(sigma, 6.0f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(at6[c] / at4[c], std::exp(-sigma[c] * 2.0f), 1e-6f);
  EXPECT_EQ(sh::causticTransmittance(sigma, -1.0f), glm::vec3(1.0f)) << "never amplifies";
}

TEST(PostfxCausticMath, SurfaceFadeRampsFromZeroAtTheSurface) {
  EXPECT_EQ(sh::causticSurfaceFade(0.0f, 1.0f), 0.0f);
  EXPECT_EQ(sh::causticSurfaceFade(-1.0f, 1.0f), 0.0f);
  EXPECT_EQ(sh::causticSurfaceFade(kNan, 1.0f), 0.0f);
  EXPECT_FLOAT_EQ(sh::causticSurfaceFade(0.5f, 1.0f), 0.5f);
  EXPECT_EQ(sh::causticSurfaceFade(2.0f, 1.0f), 1.0f);
  EXPECT_EQ(sh::causticSurfaceFade(1e-4f, 0.0f), 1.0f) << "fade disabled";
}

TEST(PostfxCausticMath, AlbedoSanitized) {
  EXPECT_EQ(sh::sanitizeAlbedo(glm::vec3(kNan, -1.0f, 7.0f)), glm::vec3(0.0f, 0.0f, 1.0f));
}

}  // namespace
