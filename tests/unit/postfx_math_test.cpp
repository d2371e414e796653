// The shader's caustic math (shaders/postfx/seabed_caustics/postfx_caustics.h) evaluated on the
// CPU.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/frame_geometry.h"
#include "core/shared_math.h"

namespace {

namespace sh = postfx::shared;
const float kNan = std::numeric_limits<float>::quiet_NaN();
const float kInf = std::numeric_limits<float>::infinity();

TEST(PostfxCausticMath, OmegaIsOneForTheUnperturbedRayAndDecaysWithItsDeviation) {
  const glm::vec3 down(0, -1, 0);
  EXPECT_EQ(sh::causticOmegaOfDeviation(down, down, 60.0f), 1.0f);
  const float angle = 0.1f;
  const glm::vec3 tilted(std::sin(angle), -std::cos(angle), 0.0f);
  EXPECT_FLOAT_EQ(sh::causticOmegaOfDeviation(tilted, down, 60.0f),
                  std::exp(-60.0f * std::sin(angle) * std::sin(angle)));
  EXPECT_EQ(sh::causticOmegaOfDeviation(tilted, down, 0.0f), 1.0f) << "tau 0: uniform light";
  EXPECT_EQ(sh::causticOmegaOfDeviation(glm::vec3(1, 0, 0), down, 1e6f), 0.0f) << "underflow";
  // The faintest ripple at the largest tau: 1 - cos^2 would lose it to rounding.
  const float tiny = 1e-4f;
  const glm::vec3 ripple(std::sin(tiny), -std::cos(tiny), 0.0f);
  EXPECT_NEAR(sh::causticOmegaOfDeviation(ripple, down, 1e6f), std::exp(-1e6 * 1e-8), 1e-4);
}

TEST(PostfxCausticMath, FlatWaterGivesOmegaOneForAnySunAboveTheHorizon) {
  for (double elevation : {90.0, 45.0, 10.0, 0.01}) {
    const double e = glm::radians(elevation);
    const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
    const float omega =
        sh::causticFactor(glm::vec3(sun), glm::vec3(0, 1, 0), 1.0f / 1.333f, 1e6f, 0.5f);
    EXPECT_NEAR(omega, 1.0f, 1e-5f) << elevation;
  }
}

TEST(PostfxCausticMath, FactorBoundedForAnyNormal) {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.01f, 0.2f));
  for (float sx = -70.0f; sx <= 70.0f; sx += 3.5f) {
    const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, -0.5f * sx));
    const float omega = sh::causticFactor(sun, n, 0.75f, 30.0f, 0.3f);
    EXPECT_TRUE(omega >= 0.0f && omega <= 1.0f) << sx;
  }
}

// The factor must equal the textbook form that builds the refracted and reflected rays with
// refract()/reflect() (GLSL's definitions, as glm's) and takes a^2 = sin^2 of each one's angle
// to its flat-water ray, in double.
double omegaOfDeviation(const glm::dvec3& ray, const glm::dvec3& unperturbed, double tau) {
  if (glm::length(ray) == 0.0) return std::exp(-tau);  // total internal reflection
  const double sine = glm::length(glm::cross(glm::normalize(ray), glm::normalize(unperturbed)));
  return std::exp(-tau * sine * sine);
}

double factorFromRays(const glm::dvec3& sun, const glm::dvec3& n, double eta, double tau,
                      double reflectionWeight) {
  const glm::dvec3 up(0.0, 1.0, 0.0);
  const double t = omegaOfDeviation(glm::refract(-sun, n, eta), glm::refract(-sun, up, eta), tau);
  const double r = omegaOfDeviation(glm::reflect(-sun, n), glm::reflect(-sun, up), tau);
  return t + (r - t) * reflectionWeight;
}

TEST(PostfxCausticMath, FactorEqualsDeviationOfRefractAndReflectInDouble) {
  double worst = 0.0;
  int cases = 0;
  for (double elevation : {89.9, 60.0, 20.0, 3.0}) {
    const double e = glm::radians(elevation);
    const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
    // eta > 1 with steep normals reaches total internal reflection (refract() gives 0).
    for (float eta : {1.0f / 1.333f, 1.0f / 1.34f, 1.0f, 1.5f}) {
      for (float sx = -3.0f; sx <= 3.0f; sx += 0.37f) {
        for (float sz = -3.0f; sz <= 3.0f; sz += 0.41f) {
          const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, sz));
          for (float tau : {0.0f, 60.0f, 800.0f}) {
            if (eta > 1.0f && std::sqrt(1.0 - sun.y * sun.y) * double(eta) > 1.0)
              continue;  // no flat ray
            const double expected = factorFromRays(sun, glm::dvec3(n), eta, tau, 0.25);
            const float got = sh::causticFactor(glm::vec3(sun), n, eta, tau, 0.25f);
            worst = std::max(worst, std::abs(static_cast<double>(got) - expected));
            ++cases;
          }
        }
      }
    }
  }
  std::printf("factor vs refract/reflect in double: worst |difference| %.3g over %d cases\n", worst,
              cases);
  // |d omega / da| = 2 tau a omega peaks at sqrt(2 tau / e) ~ 24 for tau 800, so float rounding
  // of the rays (~1e-6 of a on a steep back-lit facet: slope 2.55, eta 1, the worst case here,
  // 3.1e-5) moves omega by a few 1e-5.
  EXPECT_LT(worst, 5e-5);
}

// Ray deviation's single reference [1] across the plane of incidence made the pattern streak along
// the sun's azimuth: a tilt of the water along that plane did not dim the light at all. With the
// whole deviation, a sun at the zenith sees every tilt direction alike, and a high sun nearly so.
TEST(PostfxCausticMath, FactorIsIsotropicForAZenithSun) {
  const glm::vec3 zenith(0.0f, 1.0f, 0.0f);
  for (float slope : {0.02f, 0.05f, 0.1f, 0.3f}) {
    const float reference = sh::causticFactor(zenith, sh::waterNormalFromSlopes({slope, 0.0f}),
                                              1.0f / 1.333f, 800.0f, 0.25f);
    EXPECT_LT(reference, 1.0f) << "a tilt dims the light, " << slope;
    for (float angle = 0.0f; angle < 6.2832f; angle += 0.3f) {
      const glm::vec2 tilt(slope * std::cos(angle), slope * std::sin(angle));
      const float omega =
          sh::causticFactor(zenith, sh::waterNormalFromSlopes(tilt), 1.0f / 1.333f, 800.0f, 0.25f);
      EXPECT_NEAR(omega, reference, 1e-5f) << slope << " at " << angle;
    }
  }
  // A sun 60 degrees high: a tilt along the plane of incidence dims it as much as one across,
  // within the refraction's own foreshortening (the paper's factor: 1 along, exp(-tau a^2) across).
  const glm::vec3 sun = glm::normalize(glm::vec3(0.5f, std::sqrt(3.0f) / 2.0f, 0.0f));
  const float along =
      sh::causticFactor(sun, sh::waterNormalFromSlopes({0.05f, 0.0f}), 0.75f, 800.0f, 0.0f);
  const float across =
      sh::causticFactor(sun, sh::waterNormalFromSlopes({0.0f, 0.05f}), 0.75f, 800.0f, 0.0f);
  const double ratio = std::log(along) / std::log(across);  // ratio of the two a^2
  EXPECT_GT(ratio, 0.5);
  EXPECT_LT(ratio, 2.0);
}

// The god rays' factor (the paper's: only the deviation across the plane of incidence) is written
// with dot products; it must equal refract()/reflect() dotted with that plane's normal.
TEST(PostfxCausticMath, AcrossIncidenceFactorEqualsRefractAndReflect) {
  double worst = 0.0;
  for (double elevation : {89.9, 60.0, 20.0, 3.0}) {
    const double e = glm::radians(elevation);
    const glm::dvec3 sun(std::cos(e) * 0.6, std::sin(e), std::cos(e) * 0.8);
    const glm::vec3 across(postfx::detail::incidencePlaneNormal(sun));
    for (float eta : {1.0f / 1.333f, 1.0f, 1.5f}) {
      for (float sx = -3.0f; sx <= 3.0f; sx += 0.37f) {
        for (float sz = -3.0f; sz <= 3.0f; sz += 0.41f) {
          const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, sz));
          const glm::vec3 refracted = glm::refract(-glm::vec3(sun), n, eta);
          const glm::vec3 reflected = glm::reflect(-glm::vec3(sun), n);
          const float t = sh::causticOmegaOfCosine(glm::dot(refracted, across), 800.0f);
          const float r = sh::causticOmegaOfCosine(glm::dot(reflected, across), 800.0f);
          const float got =
              sh::causticFactorAcrossIncidence(glm::vec3(sun), n, eta, across, 800.0f, 0.25f);
          worst = std::max(worst, std::abs(static_cast<double>(got - (t + (r - t) * 0.25f))));
        }
      }
    }
  }
  EXPECT_LT(worst, 1e-5);  // float rounding of the cosines times |d omega / da| <= 24
  // Tilting the water along the plane of incidence leaves it at 1: why the seabed uses the
  // whole deviation instead (FactorIsIsotropicForAZenithSun).
  const glm::vec3 zenith(0.0f, 1.0f, 0.0f);
  EXPECT_FLOAT_EQ(sh::causticFactorAcrossIncidence(zenith, sh::waterNormalFromSlopes({0.0f, 0.1f}),
                                                   0.75f, glm::vec3(1, 0, 0), 800.0f, 0.0f),
                  1.0f);
}

TEST(PostfxCausticMath, DispersedFactorIsThePerChannelFactor) {
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.8f, 0.2f));
  const glm::vec3 eta(1.0f / 1.331f, 1.0f / 1.337f, 1.0f / 1.343f);
  for (float sx = -1.0f; sx <= 1.0f; sx += 0.13f) {
    const glm::vec3 n = sh::waterNormalFromSlopes(glm::vec2(sx, 0.7f * sx));
    const glm::vec3 rgb = sh::causticFactorRgb(sun, n, eta, 800.0f, 0.25f);
    for (int c = 0; c < 3; ++c)
      EXPECT_FLOAT_EQ(rgb[c], sh::causticFactor(sun, n, eta[c], 800.0f, 0.25f)) << sx;
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
