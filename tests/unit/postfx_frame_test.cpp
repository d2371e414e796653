// CPU side of a dispatch: the uniform block built in double, the skip test, value validation.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "core/shadow_light.h"
#include "core/validation.h"
#include "core/visibility.h"
#include "seabed_caustics/caustics_constants.h"

namespace {

using namespace postfx;

FrameDesc baseFrame() {
  FrameDesc f;
  f.camera.position = {3.0, -2.0, 5.0};
  f.camera.view = glm::lookAt(glm::vec3(0), glm::vec3(0, -0.5f, -1), glm::vec3(0, 1, 0));
  f.camera.projection = glm::perspective(1.0, 16.0 / 9.0, 0.1, 500.0);
  f.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  f.water.cascadeCount = 3;
  return f;
}

TEST(PostfxFrameConstants, TileOffsetsAtAMillionMetresMatchTheOrigin) {
  const CreateDesc create;
  FrameDesc near = baseFrame();
  FrameDesc far = near;
  far.camera.position += glm::dvec3(1e6, 1e6, -1e6);
  far.water.level += 1e6;
  const auto a = detail::buildCausticsBlock(create, near, 128, 72, {64, 64});
  const auto b = detail::buildCausticsBlock(create, far, 128, 72, {64, 64});
  for (int c = 0; c < 3; ++c) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(a.cascadeAxes[c][k], b.cascadeAxes[c][k], 1e-6f) << c << "," << k;
    }
    EXPECT_NEAR(a.cascadeOblique[c].x, b.cascadeOblique[c].x, 1e-6f);
    EXPECT_NEAR(a.cascadeOblique[c].y, b.cascadeOblique[c].y, 1e-6f);
  }
  EXPECT_EQ(a.depthAndWater.z, b.depthAndWater.z) << "level relative to camera";
}

TEST(PostfxFrameConstants, TileFractionInUnitRange) {
  for (double x : {-1e9, -64.0, -1e-12, 0.0, 1e-12, 63.999999, 64.0, 1e6 + 0.5, 1e12}) {
    const double f = detail::tileFraction(x, 64.0);
    EXPECT_GE(f, 0.0) << x;
    EXPECT_LT(f, 1.0) << x;
  }
  EXPECT_DOUBLE_EQ(detail::tileFraction(1e6 + 16.0, 64.0), 0.25);
}

TEST(PostfxFrameConstants, RefractedSunAndReference) {
  const glm::dvec3 zenith(0, 1, 0);
  const glm::dvec3 straight = detail::refractedSunDown(zenith, 1.333);
  EXPECT_NEAR(glm::length(straight - glm::dvec3(0, -1, 0)), 0.0, 1e-15);
  EXPECT_EQ(detail::incidencePlaneNormal(zenith), glm::dvec3(1, 0, 0));
  const glm::dvec3 grazing = glm::normalize(glm::dvec3(1.0, 1e-6, 0.0));
  const glm::dvec3 t = detail::refractedSunDown(grazing, 1.333);
  EXPECT_NEAR(std::asin(-t.x), std::asin(1.0 / 1.333), 1e-5) << "critical angle, away from the sun";
  const glm::dvec3 h = detail::incidencePlaneNormal(grazing);
  EXPECT_NEAR(glm::dot(h, t), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(h, grazing), 0.0, 1e-12);
}

TEST(PostfxVisibility, SkipOnlyWhenTheFrustumStaysAboveTheWater) {
  const glm::dmat4 proj = glm::perspective(1.0, 1.5, 0.1, 200.0);
  auto rotation = [](glm::vec3 dir) {
    return detail::viewToWorldRotation(glm::lookAt(glm::vec3(0), dir, glm::vec3(0, 1, 0)));
  };
  const glm::dmat3 up = rotation({0, 0.6f, -1}), down = rotation({0, -0.6f, -1});
  constexpr auto kNegOne = DepthConvention::ForwardNegOneToOne;
  constexpr auto kReverse = DepthConvention::ReverseZ;
  EXPECT_TRUE(detail::frustumReachesBelowWater(up, proj, kNegOne, 1e-4)) << "camera under water";
  EXPECT_TRUE(detail::frustumReachesBelowWater(up, proj, kNegOne, 0.0)) << "camera at the level";
  EXPECT_FALSE(detail::frustumReachesBelowWater(up, proj, kNegOne, -1.0))
      << "looking up from above";
  EXPECT_TRUE(detail::frustumReachesBelowWater(down, proj, kNegOne, -10.0)) << "looking down";
  EXPECT_FALSE(detail::frustumReachesBelowWater(down, proj, kNegOne, -1e4))
      << "far plane too short";
  // Infinite reverse-Z: any downward edge reaches every depth.
  glm::dmat4 infinite(0.0);
  infinite[0][0] = 1.0;
  infinite[1][1] = 1.5;
  infinite[2][3] = -1.0;
  infinite[3][2] = 0.1;
  EXPECT_TRUE(detail::frustumReachesBelowWater(down, infinite, kReverse, -1e6));
  EXPECT_FALSE(detail::frustumReachesBelowWater(rotation({0, 1, -0.2f}), infinite, kReverse, -1.0));
}

// The shadow bias is in metres along the light the map looks from: the direction read off the
// matrix must point toward the light in every convention, and a perspective map gives its eye.
TEST(PostfxShadowLight, PointsTowardTheLightTheMapLooksFrom) {
  const glm::dvec3 toSun = glm::normalize(glm::dvec3(0.3, 1.0, -0.4));
  const glm::dvec3 centre(1e6, -20.0, 3e5);  // far from the origin: the result must not care
  const glm::dmat4 view = glm::lookAt(centre + 50.0 * toSun, centre, glm::dvec3(0, 0, 1));
  struct Case {
    glm::dmat4 projection;
    DepthConvention convention;
  };
  glm::dmat4 reverse = glm::orthoRH_ZO(-10.0, 10.0, -10.0, 10.0, 0.0, 100.0);
  reverse[2][2] = -reverse[2][2];  // z' = 1 - z: near at 1
  reverse[3][2] = 1.0 - reverse[3][2];
  const Case cases[] = {
      {glm::orthoRH_ZO(-10.0, 10.0, -10.0, 10.0, 0.0, 100.0), DepthConvention::ForwardZeroToOne},
      {glm::orthoRH_NO(-10.0, 10.0, -10.0, 10.0, 0.0, 100.0), DepthConvention::ForwardNegOneToOne},
      {reverse, DepthConvention::ReverseZ},
  };
  for (const Case& c : cases) {
    const detail::ShadowLight light = detail::shadowLight(c.projection * view, c.convention);
    EXPECT_FALSE(light.perspective);
    EXPECT_NEAR(glm::dot(light.vector, toSun), 1.0, 1e-9) << toString(c.convention);
  }
  const glm::dmat4 spot = glm::perspectiveRH_ZO(1.0, 1.0, 0.5, 100.0) * view;
  const detail::ShadowLight light = detail::shadowLight(spot, DepthConvention::ForwardZeroToOne);
  EXPECT_TRUE(light.perspective);
  EXPECT_LT(glm::length(light.vector - (centre + 50.0 * toSun)), 1e-6 * 1e6);
  // Texel size: a 20 m wide orthographic map has 2 / |row 0| = 20 m of clip x per unit.
  EXPECT_NEAR(detail::clipUnitsToMetres(cases[0].projection * view).x, 20.0, 1e-9);
}

TEST(PostfxValidation, RejectsNaNAndOutOfRangeValues) {
  const CreateDesc create;
  std::string error;
  EXPECT_EQ(detail::validateFrameValues(create, baseFrame(), error), Result::Ok) << error;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  auto expectInvalid = [&](auto spoil, const char* mentions) {
    FrameDesc f = baseFrame();
    spoil(f);
    EXPECT_EQ(detail::validateFrameValues(create, f, error), Result::InvalidArgument) << mentions;
    EXPECT_NE(error.find(mentions), std::string::npos) << error;
  };
  expectInvalid([&](FrameDesc& f) { f.caustics.tau = nan; }, "tau");
  expectInvalid([&](FrameDesc& f) { f.caustics.tau = 2e6f; }, "tau");
  expectInvalid([&](FrameDesc& f) { f.caustics.lodBias = nan; }, "lodBias");
  expectInvalid([&](FrameDesc& f) { f.caustics.surfaceFadeDepth = -1.0f; }, "surfaceFadeDepth");
  expectInvalid([&](FrameDesc& f) { f.sun.irradiance.g = nan; }, "irradiance");
  expectInvalid([&](FrameDesc& f) { f.water.absorption.b = -0.1f; }, "absorption");
  expectInvalid([&](FrameDesc& f) { f.water.cascadeCount = 0; }, "cascadeCount");
  expectInvalid([&](FrameDesc& f) { f.camera.projection[2][2] = double(nan); }, "projection");
}

// Each pass has one stable, distinct name, and the former enumerator names still compile as
// the same values (a host renames at leisure).
TEST(PostfxNames, PassesHaveOneNameAndFormerNamesAreAliases) {
  std::set<std::string> names;
  for (int p = 0; p < kPassCount; ++p) {
    const std::string name = toString(Pass(p));
    EXPECT_NE(name, "unknown");
    EXPECT_EQ(name.find_first_not_of("abcdefghijklmnopqrstuvwxyz_"), std::string::npos) << name;
    EXPECT_TRUE(names.insert(name).second) << name;
  }
  EXPECT_STREQ(toString(Pass::WavefrontAreaRatio), "wavefront_area_ratio");
  EXPECT_STREQ(toString(Pass::TileIrradiance), "tile_irradiance");
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
  EXPECT_EQ(Pass::CausticsIrradiance, Pass::WavefrontAreaRatio);
  EXPECT_EQ(Pass::CausticsTileIrradiance, Pass::TileIrradiance);
  EXPECT_EQ(Feature::PhysicalCaustics, Feature::WavefrontAreaRatio);
#pragma GCC diagnostic pop
}

}  // namespace
