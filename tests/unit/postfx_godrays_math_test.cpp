// The god-ray march math (shaders/postfx/god_rays/postfx_godrays.h) and the CPU grid snapping
// (godrays_constants), evaluated on the CPU exactly as the shader does.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "core/shared_math.h"
#include "god_rays/godrays_constants.h"

namespace {

namespace sh = postfx::shared;
const float kNan = std::numeric_limits<float>::quiet_NaN();

TEST(PostfxGodRayMath, FirstCrossingIsTheNextPlaneAhead) {
  // Offset 0.3 in cells of 1: forward reaches 1 at t = 0.7, backward reaches 0 at t = 0.3.
  EXPECT_FLOAT_EQ(sh::godRayFirstCrossing(0.3f, 1.0f, 1.0f, 0.0f), 0.7f);
  EXPECT_FLOAT_EQ(sh::godRayFirstCrossing(0.3f, -1.0f, 1.0f, 0.0f), 0.3f);
  EXPECT_FLOAT_EQ(sh::godRayFirstCrossing(0.3f, 0.5f, 1.0f, 0.0f), 1.4f);
  // From a later start: position 0.3 + 2.0 = 2.3, next plane 3 at t = 2.7.
  EXPECT_FLOAT_EQ(sh::godRayFirstCrossing(0.3f, 1.0f, 1.0f, 2.0f), 2.7f);
}

TEST(PostfxGodRayMath, CameraOnAPlaneTakesNoZeroLengthStep) {
  for (float direction : {1.0f, -1.0f, 0.25f, -0.25f}) {
    const float t = sh::godRayFirstCrossing(0.0f, direction, 0.5f, 0.0f);
    EXPECT_FLOAT_EQ(t, 0.5f / std::abs(direction)) << direction;
  }
  // Starting on a plane later along the ray: 0.25 + 0.75 * 1 = 1.0, a plane; next is 1.5.
  EXPECT_FLOAT_EQ(sh::godRayFirstCrossing(0.25f, 1.0f, 0.5f, 0.75f), 1.25f);
}

TEST(PostfxGodRayMath, ParallelAndNanRaysNeverCross) {
  EXPECT_EQ(sh::godRayFirstCrossing(0.3f, 0.0f, 1.0f, 0.0f), sh::GODRAYS_NEVER);
  EXPECT_EQ(sh::godRayFirstCrossing(0.3f, 1e-9f, 1.0f, 0.0f), sh::GODRAYS_NEVER);
  EXPECT_EQ(sh::godRayFirstCrossing(0.3f, kNan, 1.0f, 0.0f), sh::GODRAYS_NEVER);
  EXPECT_EQ(sh::godRayCrossingStep(0.0f, 1.0f), sh::GODRAYS_NEVER);
  EXPECT_FLOAT_EQ(sh::godRayCrossingStep(-0.5f, 1.0f), 2.0f);
}

TEST(PostfxGodRayMath, DdaVisitsEveryPlaneInOrder) {
  // 2D walk over both families; crossings must increase and match the analytic plane count.
  const float s = 0.75f, dx = 0.6f, dz = -0.8f, ox = 0.1f, oz = 0.7f;
  float tx = sh::godRayFirstCrossing(ox, dx, s, 0.0f),
        tz = sh::godRayFirstCrossing(oz, dz, s, 0.0f);
  const float sx = sh::godRayCrossingStep(dx, s), sz = sh::godRayCrossingStep(dz, s);
  float previous = 0.0f;
  int hits = 0;
  const float end = 20.0f;
  while (true) {
    const float t = std::min(tx, tz);
    if (t > end) break;
    EXPECT_GT(t, previous);
    previous = t;
    ++hits;
    if (tx <= t) tx += sx;
    if (tz <= t) tz += sz;
  }
  const int expected = int(std::floor((ox + dx * end) / s) - std::floor(ox / s)) +
                       int(std::floor(oz / s) - std::floor((oz + dz * end) / s));
  EXPECT_EQ(hits, expected);
}

TEST(PostfxGodRayMath, ParticipationFadesAtTheSurfaceAndWithDepth) {
  EXPECT_EQ(sh::godRayParticipation(0.0f, 2.0f, 40.0f), 0.0f);
  EXPECT_EQ(sh::godRayParticipation(-1.0f, 2.0f, 40.0f), 0.0f);
  EXPECT_EQ(sh::godRayParticipation(kNan, 2.0f, 40.0f), 0.0f);
  EXPECT_FLOAT_EQ(sh::godRayParticipation(1.0f, 2.0f, 0.0f), 0.5f);
  EXPECT_FLOAT_EQ(sh::godRayParticipation(10.0f, 0.0f, 40.0f), std::exp(-0.25f));
  EXPECT_FLOAT_EQ(sh::godRayParticipation(10.0f, 0.0f, 0.0f), 1.0f);
}

TEST(PostfxGodRayMath, InscatterIsBoundedAndHasTheThinLimit) {
  const glm::vec3 s(0.02f, 0.03f, 0.04f), a(0.45f, 0.07f, 0.03f);
  const glm::vec3 far = sh::godRayInscatter(s, s + a, 1e5f);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(far[c], s[c] / (s[c] + a[c]), 1e-6f);
  const glm::vec3 thin = sh::godRayInscatter(s, glm::vec3(0.0f), 3.0f);
  for (int c = 0; c < 3; ++c) EXPECT_FLOAT_EQ(thin[c], s[c] * 3.0f);
  const glm::vec3 none = sh::godRayInscatter(glm::vec3(0.0f), glm::vec3(0.0f), 3.0f);
  EXPECT_EQ(none, glm::vec3(0.0f));
  EXPECT_EQ(sh::godRayInscatter(s, s + a, 0.0f), glm::vec3(0.0f));
}

TEST(PostfxGodRayMath, UnderwaterRangeClipsAtTheSurface) {
  // Camera 2 m under the level looking up at 30 degrees: ends at 4 m.
  glm::vec2 r = sh::godRayUnderwaterRange(2.0f, 0.5f, 60.0f);
  EXPECT_FLOAT_EQ(r.x, 0.0f);
  EXPECT_FLOAT_EQ(r.y, 4.0f);
  // Camera 3 m above looking down: starts where it enters.
  r = sh::godRayUnderwaterRange(-3.0f, -0.5f, 60.0f);
  EXPECT_FLOAT_EQ(r.x, 6.0f);
  EXPECT_FLOAT_EQ(r.y, 60.0f);
  // Above looking up, or horizontal: no water.
  r = sh::godRayUnderwaterRange(-3.0f, 0.5f, 60.0f);
  EXPECT_LE(r.y, r.x);
  r = sh::godRayUnderwaterRange(-3.0f, 0.0f, 60.0f);
  EXPECT_LE(r.y, r.x);
  // Camera exactly at the level looking up: zero length.
  r = sh::godRayUnderwaterRange(0.0f, 0.5f, 60.0f);
  EXPECT_LE(r.y, r.x);
}

TEST(PostfxGodRayGrid, FrameIsOrthonormalWithUpAlongTheRefractedSun) {
  for (const glm::dvec3& sun :
       {glm::dvec3(0, 1, 0), glm::dvec3(0.6, 0.5, 0.2), glm::dvec3(-0.7, 0.01, 0.3)}) {
    const postfx::detail::GodRayGrid g = postfx::detail::godRayGrid(sun, 1.333);
    EXPECT_NEAR(glm::length(g.x), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(g.y), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(g.z), 1.0, 1e-12);
    EXPECT_NEAR(glm::dot(g.x, g.y), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(g.x, g.z), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(g.y, g.z), 0.0, 1e-12);
    EXPECT_GT(g.y.y, 0.6) << "refracted sun is steeper than the critical angle";
  }
}

TEST(PostfxGodRayGrid, PhaseIsSnappedInDoubleFarFromTheOrigin) {
  using postfx::detail::godRayGridPhase;
  EXPECT_DOUBLE_EQ(godRayGridPhase(1e6 + 0.25, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(godRayGridPhase(-0.25, 0.5), 0.25);
  EXPECT_DOUBLE_EQ(godRayGridPhase(-1e6, 0.5), 0.0);
  const double p = godRayGridPhase(-1e-17, 0.5);  // rounds onto the bound
  EXPECT_GE(p, 0.0);
  EXPECT_LT(p, 0.5);
}

// Circular distance between two phases in [0, spacing).
double phaseDistance(double a, double b, double spacing) {
  const double d = std::abs(a - b);
  return std::min(d, spacing - d);
}

TEST(PostfxGodRayGrid, PivotKeepsEveryPlaneInPlaceWhileTheSunHoldsStill) {
  using postfx::detail::godRayGridPhase;
  const double spacing = 0.75;
  const postfx::detail::GodRayGrid grid =
      postfx::detail::godRayGrid(glm::dvec3(0.6, 0.5, 0.2), 1.333);
  postfx::detail::GodRayGridPivot pivot;
  double worst = 0.0;
  for (const glm::dvec3& camera :
       {glm::dvec3(0.1, -3, 0.2), glm::dvec3(13.7, -4, -2.2), glm::dvec3(1e6, -5, -2e6),
        glm::dvec3(1e6 + 0.31, -5.2, -2e6 + 0.07), glm::dvec3(-3.3, -1, 8.8)}) {
    const glm::dvec3 relative = camera - pivot.follow(grid, spacing, camera);
    for (const glm::dvec3& axis : {grid.x, grid.z}) {
      // The planes through the world origin: where they were before the pivot moved.
      worst =
          std::max(worst, phaseDistance(godRayGridPhase(glm::dot(relative, axis), spacing),
                                        godRayGridPhase(glm::dot(camera, axis), spacing), spacing));
    }
    EXPECT_LT(glm::length(relative - glm::dot(relative, grid.y) * grid.y), spacing)
        << "the pivot is a lattice point next to the camera";
  }
  std::printf("static sun: planes moved by at most %.3g m as the pivot followed the camera\n",
              worst);
  EXPECT_LT(worst, 1e-6);
}

TEST(PostfxGodRayGrid, SettingSunFarFromTheOriginMovesNearbyPlanesOnlySlightly) {
  using postfx::detail::godRayGridPhase;
  const double spacing = 0.75, turn = 1e-4;  // radians per frame: a 17-minute day
  const glm::dvec3 camera(1e6, -5.0, -2e6);
  postfx::detail::GodRayGridPivot pivot;
  double pivotPrevious[2] = {0, 0}, originPrevious[2] = {0, 0};
  double pivotWorst = 0.0, originWorst = 0.0;
  for (int frame = 0; frame < 10; ++frame) {
    const double azimuth = 0.3 + turn * frame;
    const glm::dvec3 sun(0.7 * std::cos(azimuth), 0.7, 0.7 * std::sin(azimuth));
    const postfx::detail::GodRayGrid grid = postfx::detail::godRayGrid(sun, 1.333);
    const glm::dvec3 relative = camera - pivot.follow(grid, spacing, camera);
    const glm::dvec3 axes[2] = {grid.x, grid.z};
    for (int i = 0; i < 2; ++i) {
      const double withPivot = godRayGridPhase(glm::dot(relative, axes[i]), spacing);
      const double fromOrigin = godRayGridPhase(glm::dot(camera, axes[i]), spacing);
      if (frame > 0) {
        pivotWorst = std::max(pivotWorst, phaseDistance(withPivot, pivotPrevious[i], spacing));
        originWorst = std::max(originWorst, phaseDistance(fromOrigin, originPrevious[i], spacing));
      }
      pivotPrevious[i] = withPivot;
      originPrevious[i] = fromOrigin;
    }
  }
  std::printf(
      "sun turning 1e-4 rad/frame, camera 2.2e6 m out: nearby planes move %.3g m/frame "
      "about the pivot, %.3g m/frame about the world origin (spacing %.2f m)\n",
      pivotWorst, originWorst, spacing);
  // About the pivot: |camera - pivot| <= spacing * sqrt(2), so spacing * sqrt(2) * turn ~ 1e-4.
  EXPECT_LT(pivotWorst, 2.0 * spacing * turn);
  EXPECT_GT(originWorst, 0.1) << "the case is meant to show the reshuffle about the origin";
}

}  // namespace
