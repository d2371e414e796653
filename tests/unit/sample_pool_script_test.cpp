// The pool's script (sample_app/src/pool_script.h): drops at fixed times on places that depend
// on nothing but their number, so any split of the clock into frames gives the same drops, and
// the ball's path stays inside the pool.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "pool_script.h"

namespace {

using ocean::PoolScript;
using ocean::ScriptedDrop;

bool same(const ScriptedDrop& a, const ScriptedDrop& b) {
  return a.time == b.time && a.centre == b.centre && a.radius == b.radius &&
         a.strength == b.strength;
}

TEST(PoolScript, AnySplitOfTheClockGivesTheSameDrops) {
  const PoolScript script;
  const std::vector<ScriptedDrop> whole = ocean::dropsBetween(script, -4.0, 10.0);
  // Frames at 30 fps and at an uneven clock both add up to the same drops, bit for bit.
  for (double step : {1.0 / 30.0, 0.37}) {
    std::vector<ScriptedDrop> pieces;
    for (double t = -4.0; t < 10.0; t += step) {
      const auto part = ocean::dropsBetween(script, t, std::min(t + step, 10.0));
      pieces.insert(pieces.end(), part.begin(), part.end());
    }
    ASSERT_EQ(pieces.size(), whole.size()) << "step " << step;
    for (size_t i = 0; i < whole.size(); ++i) EXPECT_TRUE(same(pieces[i], whole[i])) << i;
  }
  // Drop k at k * 0.7 s for k = -5 .. 14, each inside the pool with a sane size.
  ASSERT_EQ(whole.size(), 20u);
  for (size_t i = 0; i < whole.size(); ++i) {
    EXPECT_DOUBLE_EQ(whole[i].time, (double(i) - 5.0) * script.dropInterval);
    EXPECT_LE(std::abs(whole[i].centre.x), 3.5);
    EXPECT_LE(std::abs(whole[i].centre.y), 3.5);
    EXPECT_GT(whole[i].radius, 0.05);
    EXPECT_LE(std::abs(whole[i].strength), 0.05);
  }
  // Not all in one place: the hash spreads them.
  EXPECT_NE(whole[0].centre, whole[1].centre);
}

TEST(PoolScript, EmptyOrBadIntervalsGiveNoDrops) {
  const PoolScript script;
  EXPECT_TRUE(ocean::dropsBetween(script, 2.0, 2.0).empty());
  EXPECT_TRUE(ocean::dropsBetween(script, 3.0, 2.0).empty());
  EXPECT_TRUE(ocean::dropsBetween(script, NAN, 2.0).empty());
  EXPECT_TRUE(ocean::dropsBetween(script, 0.0, INFINITY).empty());
  PoolScript none = script;
  none.dropInterval = 0.0;
  EXPECT_TRUE(ocean::dropsBetween(none, 0.0, 5.0).empty());
  // A huge interval gives its last 10^5 drops, not a hang.
  EXPECT_EQ(ocean::dropsBetween(script, 0.0, 1e9).size(), 100000u);
}

TEST(PoolScript, TheBallStaysInThePoolAndBreaksTheSurface) {
  const PoolScript script;
  double lowest = 1e9, highest = -1e9;
  glm::dvec3 previous = ocean::sphereCentre(script, 0.0);
  for (double t = 0.0; t < 260.0; t += 0.01) {
    const glm::dvec3 c = ocean::sphereCentre(script, t);
    EXPECT_LE(std::abs(c.x) + script.sphereRadius, 0.5 * script.poolSize.x);
    EXPECT_LE(std::abs(c.z) + script.sphereRadius, 0.5 * script.poolSize.y);
    EXPECT_LE(glm::length(c - previous) / 0.01, 1.5);  // m/s
    lowest = std::min(lowest, c.y);
    highest = std::max(highest, c.y);
    previous = c;
  }
  EXPECT_LT(lowest + script.sphereRadius, 0.0);  // wholly under at the bottom
  EXPECT_GT(highest - script.sphereRadius, -0.5 * script.sphereRadius);  // mostly out at the top
  // Periodic: 260 s later it is where it was.
  EXPECT_NEAR(glm::length(ocean::sphereCentre(script, 263.0) - ocean::sphereCentre(script, 3.0)),
              0.0, 1e-9);
}

}  // namespace
