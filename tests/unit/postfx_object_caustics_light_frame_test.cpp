// A local light's view of the casters (CPU): the perspective caster clip holds every caster in
// the light's reach, is the same far from the origin, and each reason to leave a light out is
// told apart (beyond range, outside the cone, inside a caster, across the water level, casters
// all around it).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "object_caustics/object_caustics_light_frame.h"

namespace {

using postfx::LightSkip;
using postfx::detail::ObjectLightFrame;

postfx::CasterMesh boxAt(const glm::dvec3& position, double half = 0.5) {
  postfx::CasterMesh m;
  m.boundsMin = glm::vec3(float(-half));
  m.boundsMax = glm::vec3(float(half));
  m.modelToWorld[3] = glm::dvec4(position, 1.0);
  return m;
}

// A frame with the given casters and one light looking at `target`, its receivers a wide
// perspective map from the light (sees every caster in front of it).
struct LightScene {
  std::vector<postfx::CasterMesh> casters;
  postfx::LocalLight light;
  postfx::FrameDesc frame() const {
    postfx::FrameDesc f;
    f.water.level = -1e9;  // in air
    f.objectCaustics.casters = casters.data();
    f.objectCaustics.casterCount = int(casters.size());
    f.objectCaustics.lights = &light;
    f.objectCaustics.lightCount = 1;
    return f;
  }
};

LightScene sceneWith(const std::vector<postfx::CasterMesh>& casters, const glm::dvec3& light,
                     const glm::dvec3& target, postfx::LocalLightType type) {
  LightScene s;
  s.casters = casters;
  s.light.type = type;
  s.light.position = light;
  s.light.direction = target - light;
  s.light.range = 100.0;
  const glm::dvec3 d = glm::normalize(target - light);
  const glm::dvec3 up = std::abs(d.y) > 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  s.light.receivers.worldToLightClip = glm::perspectiveRH_ZO(glm::radians(170.0), 1.0, 0.01, 1e4) *
                                       glm::lookAtRH(light, light + d, up);
  return s;
}

// Every corner of every caster inside the caster clip (NDC within +-1, depth in [0, 1]).
void expectCornersInside(const postfx::FrameDesc& frame, const ObjectLightFrame& view) {
  const postfx::shared::ObjectCausticsBlock block =
      postfx::detail::buildObjectCausticsBlock(postfx::CreateDesc{}, frame, view, 64, 64);
  double worst = 0.0;
  for (const postfx::CasterMesh& m : std::vector<postfx::CasterMesh>(
           frame.objectCaustics.casters,
           frame.objectCaustics.casters + frame.objectCaustics.casterCount))
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 p = postfx::detail::casterWorldCorner(m, i) - view.anchor;
      const glm::dvec4 c = glm::dmat4(block.casterClip) * glm::dvec4(p, 1.0);
      ASSERT_GT(c.w, 0.0);
      const glm::dvec3 ndc = glm::dvec3(c) / c.w;
      worst = std::max({worst, std::abs(ndc.x), std::abs(ndc.y)});
      EXPECT_GE(ndc.z, 0.0);
      EXPECT_LE(ndc.z, 1.0);
    }
  std::printf("largest |ndc| of a caster corner: %.4f\n", worst);
  EXPECT_LE(worst, 1.0);
  EXPECT_GT(worst, 0.97) << "fitted, not loose";
}

TEST(PostfxObjectCausticsLightFrame, ViewHoldsTheCastersInReach) {
  for (const glm::dvec3 base : {glm::dvec3(0.0), glm::dvec3(1e6, -30.0, -2e6)}) {
    const LightScene s = sceneWith(
        {boxAt(base + glm::dvec3(0, 1, 0)), boxAt(base + glm::dvec3(1.2, 0.8, -0.4), 0.3)},
        base + glm::dvec3(0.2, 4.0, 0.5), base + glm::dvec3(0.5, 1.0, 0.0),
        postfx::LocalLightType::Point);
    ObjectLightFrame view;
    ASSERT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::None);
    EXPECT_EQ(view.casters, 3u);
    expectCornersInside(s.frame(), view);
  }
}

TEST(PostfxObjectCausticsLightFrame, EachReasonToLeaveALightOutIsToldApart) {
  using postfx::LocalLightType;
  const std::vector<postfx::CasterMesh> one = {boxAt({0, 1, 0})};
  ObjectLightFrame view;
  {  // beyond its range (the box is 2.5 m away)
    LightScene s = sceneWith(one, {0, 4, 0}, {0, 1, 0}, LocalLightType::Spot);
    s.light.range = 2.0;
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::NoCasterInReach);
    s.light.range = 2.6;
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::None);
  }
  {  // a spot pointing away
    LightScene s = sceneWith(one, {0, 4, 0}, {0, 1, 0}, LocalLightType::Spot);
    s.light.direction = {0, 1, 0};
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::NoCasterInReach);
  }
  {  // inside the box
    const LightScene s = sceneWith(one, {0.2, 1.1, 0}, {0, 1, 0}, LocalLightType::Point);
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::InsideCaster);
  }
  {  // above the water, the box below it; then both below
    const LightScene s = sceneWith(one, {0, 4, 0}, {0, 1, 0}, LocalLightType::Spot);
    postfx::FrameDesc f = s.frame();
    f.water.level = 2.0;
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(f, 0, view), LightSkip::AcrossWaterSurface);
    f.water.level = 4.0;  // a light exactly at the level counts as under water
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(f, 0, view), LightSkip::None);
    EXPECT_TRUE(view.underwater);
  }
  {  // a point light between two boxes on either side
    const LightScene s = sceneWith({boxAt({-2, 1, 0}), boxAt({2, 1, 0})}, {0, 1, 0}, {2, 1, 0},
                                   LocalLightType::Point);
    EXPECT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::CastersAround);
  }
  {  // a narrow spot: its own cone is the view
    LightScene s = sceneWith(one, {0, 4, 0}, {0, 1, 0}, LocalLightType::Spot);
    s.light.coneAngleDegrees = 4.0f;
    ASSERT_EQ(postfx::detail::fitLocalLightFrame(s.frame(), 0, view), LightSkip::None);
    EXPECT_NEAR(view.tanHalfGrid, std::tan(glm::radians(2.0)) * 1.02, 1e-9);
  }
}

}  // namespace
