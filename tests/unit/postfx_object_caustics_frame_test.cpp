// The object caustics' sun view (CPU): fitted to the casters, snapped to the ray grid so the
// rays stay put while a caster moves less than a cell (no swimming), precise far from the
// origin, and the caster clip volume holds every caster.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "object_caustics/object_caustics_frame.h"

namespace {

using postfx::detail::ObjectLightFrame;

postfx::FrameDesc frameWith(const postfx::CasterMesh& mesh, const glm::dvec3& towardSun) {
  postfx::FrameDesc f;
  f.sun.direction = glm::normalize(towardSun);
  f.water.level = -1e9;  // casters in air
  f.objectCaustics.casters = &mesh;
  f.objectCaustics.casterCount = 1;
  return f;
}

postfx::CasterMesh meshAt(const glm::dvec3& position) {
  postfx::CasterMesh m;
  m.boundsMin = glm::vec3(-1.0f);
  m.boundsMax = glm::vec3(1.0f);
  m.modelToWorld[3] = glm::dvec4(position, 1.0);
  return m;
}

// Anchor displacement in grid cells along the map axes: whole numbers when snapped.
glm::dvec2 cellsBetween(const ObjectLightFrame& a, const ObjectLightFrame& b, int gridSize) {
  const double cell = 2.0 * a.halfGrid / gridSize;
  const glm::dvec3 d = b.anchor - a.anchor;
  return glm::dvec2(glm::dot(d, a.right), glm::dot(d, a.up)) / cell;
}

TEST(PostfxObjectCausticsFrame, AnchorSnapsToWholeGridCells) {
  const glm::dvec3 sun(0.3, 1.0, -0.2);
  for (const glm::dvec3 base : {glm::dvec3(0.0), glm::dvec3(1e6, -30.0, -2e6)}) {
    const postfx::CasterMesh m0 = meshAt(base);
    const ObjectLightFrame f0 = postfx::detail::fitObjectLightFrame(frameWith(m0, sun));
    double worst = 0.0;
    for (int step = 1; step <= 40; ++step) {
      const postfx::CasterMesh m = meshAt(base + glm::dvec3(0.0123 * step, 0.004 * step, 0.0));
      const ObjectLightFrame f = postfx::detail::fitObjectLightFrame(frameWith(m, sun));
      ASSERT_EQ(f.halfGrid, f0.halfGrid);
      const glm::dvec2 cells = cellsBetween(f0, f, 256);
      worst = std::max({worst, std::abs(cells.x - std::round(cells.x)),
                        std::abs(cells.y - std::round(cells.y))});
    }
    std::printf("base (%.0f, %.0f, %.0f): worst anchor offset from whole cells %.3g cells\n",
                base.x, base.y, base.z, worst);
    EXPECT_LT(worst, 1e-6);
  }
}

TEST(PostfxObjectCausticsFrame, SideIsQuantisedInEighthOctaves) {
  const glm::dvec3 sun(0.0, 1.0, 0.0);
  postfx::CasterMesh m = meshAt(glm::dvec3(0.0));
  const double h0 = postfx::detail::fitObjectLightFrame(frameWith(m, sun)).halfGrid;
  m.modelToWorld[0][0] = m.modelToWorld[1][1] = m.modelToWorld[2][2] = 1.01;  // 1 % larger
  const double h1 = postfx::detail::fitObjectLightFrame(frameWith(m, sun)).halfGrid;
  const double octaves = std::log2(h0 * 2.0);
  std::printf("half side %.6f m -> %.6f m (log2 side %.4f)\n", h0, h1, octaves);
  EXPECT_NEAR(octaves * 8.0, std::round(octaves * 8.0), 1e-9);
  EXPECT_GE(h0, 1.02 * 1.0);  // holds the 2 m box plus its 2 % margin
  EXPECT_TRUE(h1 == h0 || std::abs(h1 / h0 - std::exp2(0.125)) < 1e-12);
}

TEST(PostfxObjectCausticsFrame, CasterClipHoldsTheCasters) {
  const glm::dvec3 sun(-0.5, 0.8, 0.4);
  const glm::dvec3 position(250.0, -3.0, 75.0);
  postfx::CasterMesh m = meshAt(position);
  const postfx::FrameDesc frame = frameWith(m, sun);
  const ObjectLightFrame f = postfx::detail::fitObjectLightFrame(frame);
  const postfx::shared::ObjectCausticsBlock b =
      postfx::detail::buildObjectCausticsBlock(postfx::CreateDesc{}, frame, f, 64, 64);
  glm::dvec3 lo(1e9), hi(-1e9);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner((i & 1) ? 1.0 : -1.0, (i & 2) ? 1.0 : -1.0, (i & 4) ? 1.0 : -1.0);
    const glm::dvec4 clip =
        glm::dmat4(b.casterClip) * glm::dvec4(position + corner - f.anchor, 1.0);
    lo = glm::min(lo, glm::dvec3(clip));
    hi = glm::max(hi, glm::dvec3(clip));
  }
  std::printf("caster clip x [%.3f, %.3f] y [%.3f, %.3f] z [%.4f, %.4f]\n", lo.x, hi.x, lo.y, hi.y,
              lo.z, hi.z);
  EXPECT_GE(lo.x, -1.0);
  EXPECT_LE(hi.x, 1.0);
  EXPECT_GE(lo.y, -1.0);
  EXPECT_LE(hi.y, 1.0);
  EXPECT_GT(lo.z, 0.0);
  EXPECT_LT(hi.z, 1.0);
  // The published map: axes perpendicular to the light, its centre on the anchor's light ray.
  const postfx::ObjectCausticMap map = postfx::detail::describeObjectCausticMap(f, 512);
  EXPECT_NEAR(glm::dot(map.axisU, map.direction), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(map.axisV, map.direction), 0.0, 1e-12);
  const glm::dvec3 centre = map.origin + 0.5 * (map.axisU + map.axisV);
  EXPECT_LT(glm::length(glm::cross(centre - f.anchor, map.direction)), 1e-9);
  EXPECT_LT(glm::length(map.direction + glm::normalize(sun)), 1e-12);
}

// A caster whose bounds never reach the receivers' map (another bay, 60 m away) lights nothing
// the map sees: the sun's map is fitted as if it were not there, not stretched over both.
TEST(PostfxObjectCausticsFrame, CastersBeyondTheReceiverMapDoNotWidenIt) {
  const glm::dvec3 sun(0.2, 1.0, 0.1);
  const postfx::CasterMesh casters[2] = {meshAt(glm::dvec3(0.0, -5.0, 0.0)),
                                         meshAt(glm::dvec3(60.0, -5.0, 0.0))};
  postfx::FrameDesc frame = frameWith(casters[0], sun);
  frame.water.level = 0.0;
  // A receiver map 20 m across around the first caster, seen straight down.
  glm::dmat4 clip(1.0);
  clip[0][0] = clip[2][1] = 0.1;
  clip[1][1] = 0.0;
  clip[1][2] = 0.01;
  clip[2][2] = 0.0;
  clip[3][2] = 0.5;
  frame.objectCaustics.receivers.worldToLightClip = clip;
  const ObjectLightFrame alone = postfx::detail::fitObjectLightFrame(frame);
  frame.objectCaustics.casters = casters;
  frame.objectCaustics.casterCount = 2;
  const ObjectLightFrame both = postfx::detail::fitObjectLightFrame(frame);
  EXPECT_EQ(both.halfGrid, alone.halfGrid);
  EXPECT_EQ(both.anchor, alone.anchor);
  EXPECT_EQ(both.zNear, alone.zNear);
  EXPECT_EQ(both.zFar, alone.zFar);
  // With the map over both, it spans both.
  clip[0][0] = 0.01;
  clip[3][0] = -0.3;
  frame.objectCaustics.receivers.worldToLightClip = clip;
  EXPECT_GT(postfx::detail::fitObjectLightFrame(frame).halfGrid, 20.0 * alone.halfGrid);
}

}  // namespace
