// The sample's ripple simulation (sample_app/src/ripple_simulation.h) on small grids: a drop's
// ring travels at the wave speed, a step keeps the volume of water, rest stays exactly at rest,
// the slopes are the heights' central differences, a plunging sphere raises the water by its
// volume, and no input leaves NaN or heights beyond the clamp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include <gl_fixture.h>

#include "ripple_simulation.h"

namespace {

using ocean::RippleDesc;
using ocean::RippleSimulation;

class RippleSimulationTest : public testsupport::GlTest {};

std::unique_ptr<RippleSimulation> make(const RippleDesc& desc) {
  std::string error;
  auto sim = RippleSimulation::create(desc, error);
  EXPECT_TRUE(sim) << error;
  return sim;
}

double heightSum(const std::vector<glm::vec4>& texels) {
  double sum = 0.0;
  for (const glm::vec4& t : texels) sum += double(t.z);
  return sum;
}

// Radius (m) of the highest crest along the row through the centre, right of it, beyond
// `minRadius`. Texel i's centre lies at u = ((i + 0.5) / n - 0.5) size.
double crestRadius(const std::vector<glm::vec4>& texels, const RippleDesc& desc, double minRadius) {
  const int n = desc.resolution;
  const int row = n / 2;
  const double dx = desc.size.x / n;
  double best = -1.0, radius = 0.0;
  for (int i = n / 2; i < n; ++i) {
    const double u = (i + 0.5) * dx - 0.5 * desc.size.x;
    if (u < minRadius) continue;
    const double h = texels[size_t(row * n + i)].z;
    if (h > best) {
      best = h;
      radius = u;
    }
  }
  return radius;
}

// A drop at the centre sends out a ring whose crest moves at the wave speed: measured between
// 0.75 s and 1.75 s, so the drop's own width cancels (the row read lies half a texel, 3 cm, off
// the centre).
TEST_F(RippleSimulationTest, RingTravelsAtTheWaveSpeed) {
  RippleDesc desc;
  desc.resolution = 128;
  desc.size = {8.0, 8.0};
  desc.waveSpeed = 1.2;
  desc.damping = 0.0;
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  ASSERT_TRUE(sim->addDrop({0.0, 0.0}, 0.25, 0.02));
  const int perSecond = sim->stepsPerSecond();
  sim->step(int(0.75 * perSecond));
  const double t1 = int(0.75 * perSecond) * sim->stepSeconds();
  const double r1 = crestRadius(sim->read(), desc, 0.3);
  sim->step(perSecond);
  const double t2 = t1 + perSecond * sim->stepSeconds();
  const double r2 = crestRadius(sim->read(), desc, 0.3);
  const double speed = (r2 - r1) / (t2 - t1);
  std::printf("crest at %.3f m after %.3f s, %.3f m after %.3f s: %.3f m/s (c = %.2f)\n", r1, t1,
              r2, t2, speed, desc.waveSpeed);
  // The crest's place is read to a texel (1/16 m) at each end: 0.09 m/s of slack, plus the
  // grid's own dispersion, which slows the shortest waves a little.
  EXPECT_NEAR(speed, desc.waveSpeed, 0.1 * desc.waveSpeed) << "r1 " << r1 << " r2 " << r2;
  // And the crest is where c t puts it, within the drop's radius.
  EXPECT_NEAR(r2, desc.waveSpeed * t2, 0.25) << "t2 " << t2;
}

// Reflecting walls and a Laplacian that sums to zero: the steps keep the sum of heights. Float
// rounding is all that moves it: under 1e-5 of the sum of |h| after 600 steps.
TEST_F(RippleSimulationTest, StepKeepsTheVolume) {
  RippleDesc desc;
  desc.resolution = 64;
  desc.size = {4.0, 3.0};
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  ASSERT_TRUE(sim->addDrop({0.7, -0.4}, 0.4, 0.08));
  ASSERT_TRUE(sim->addDrop({-1.9, 1.4}, 0.3, -0.05));  // across the corner: part of it inside
  ASSERT_TRUE(sim->addDrop({0.0, 0.9}, 0.2, 0.06));
  const std::vector<glm::vec4> before = sim->read();
  double absolute = 0.0;
  for (const glm::vec4& t : before) absolute += std::abs(double(t.z));
  const double volumeBefore = heightSum(before);
  sim->step(600);
  const double volumeAfter = heightSum(sim->read());
  std::printf("sum of heights %.9g before, %.9g after 600 steps (sum |h| %.6g)\n", volumeBefore,
              volumeAfter, absolute);
  EXPECT_NEAR(volumeAfter, volumeBefore, 1e-5 * absolute)
      << "before " << volumeBefore << " after " << volumeAfter << " sum|h| " << absolute;
}

TEST_F(RippleSimulationTest, RestStaysExactlyAtRest) {
  RippleDesc desc;
  desc.resolution = 32;
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  sim->step(50);
  for (const glm::vec4& t : sim->read()) ASSERT_EQ(t, glm::vec4(0.0f));
  // After waves, reset() is rest again, and stays so.
  ASSERT_TRUE(sim->addDrop({0.5, 0.5}, 1.0, 0.1));
  sim->step(20);
  sim->reset();
  sim->step(20);
  for (const glm::vec4& t : sim->read()) ASSERT_EQ(t, glm::vec4(0.0f));
  // A sphere that stays above the water, or one that does not move, changes nothing.
  ASSERT_TRUE(sim->moveSphere({0.0, 2.0, 0.0}, {1.0, 2.0, 0.5}, 0.5));
  ASSERT_TRUE(sim->moveSphere({0.0, -1.0, 0.0}, {0.0, -1.0, 0.0}, 0.5));
  for (const glm::vec4& t : sim->read()) ASSERT_EQ(t, glm::vec4(0.0f));
}

// RG are (h[i+1] - h[i-1]) / 2dx and (h[j+1] - h[j-1]) / 2dz, an edge's outer neighbour being
// itself; B is the height. On a rectangle whose texels are not square.
TEST_F(RippleSimulationTest, SlopesAreCentralDifferences) {
  RippleDesc desc;
  desc.resolution = 48;
  desc.size = {6.0, 3.0};
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  ASSERT_TRUE(sim->addDrop({0.4, 0.2}, 0.9, 0.05));
  ASSERT_TRUE(sim->addDrop({-2.9, -1.4}, 0.6, -0.04));
  sim->step(30);
  const std::vector<glm::vec4> t = sim->read();
  const int n = desc.resolution;
  const double dx = desc.size.x / n, dz = desc.size.y / n;
  auto h = [&](int i, int j) {
    i = std::clamp(i, 0, n - 1);
    j = std::clamp(j, 0, n - 1);
    return double(t[size_t(j * n + i)].z);
  };
  double largest = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const double su = (h(i + 1, j) - h(i - 1, j)) / (2.0 * dx);
      const double sv = (h(i, j + 1) - h(i, j - 1)) / (2.0 * dz);
      largest = std::max({largest, std::abs(su), std::abs(sv)});
      ASSERT_NEAR(t[size_t(j * n + i)].x, su, 1e-6 + 1e-5 * std::abs(su)) << i << "," << j;
      ASSERT_NEAR(t[size_t(j * n + i)].y, sv, 1e-6 + 1e-5 * std::abs(sv)) << i << "," << j;
    }
  }
  EXPECT_GT(largest, 0.01);  // the comparison saw real slopes
}

// A sphere of radius R plunged from above the water to below it pushes its volume, 4/3 pi R^3,
// into the surface: the sum of heights times a texel's area is that volume, within the grid's
// sampling of the sphere's chords (1 %), and the steps keep it.
TEST_F(RippleSimulationTest, PlungingSphereRaisesTheWaterByItsVolume) {
  RippleDesc desc;
  desc.resolution = 128;
  desc.size = {8.0, 8.0};
  desc.maxHeight = 5.0;  // the whole chord, 1.2 m, must fit under the clamp for this balance
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  const double radius = 0.6;
  ASSERT_TRUE(sim->moveSphere({0.3, 2.0, -0.2}, {0.3, -1.0, -0.2}, radius));
  const double texelArea = (desc.size.x / desc.resolution) * (desc.size.y / desc.resolution);
  const double sphereVolume = 4.0 / 3.0 * M_PI * radius * radius * radius;
  const double pushed = heightSum(sim->read()) * texelArea;
  std::printf("sphere volume %.5f m^3, surface raised by %.5f m^3\n", sphereVolume, pushed);
  EXPECT_NEAR(pushed, sphereVolume, 0.01 * sphereVolume);
  sim->step(200);
  EXPECT_NEAR(heightSum(sim->read()) * texelArea, sphereVolume, 0.01 * sphereVolume);
}

// Extreme and invalid input: huge drops and spheres are clamped, NaN and infinities refused;
// hundreds of steps later every texel is finite and within the height clamp.
TEST_F(RippleSimulationTest, ExtremeDropsLeaveNoNaN) {
  RippleDesc desc;
  desc.resolution = 64;
  desc.size = {2.0, 2.0};
  desc.maxHeight = 0.3;
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  EXPECT_FALSE(sim->addDrop({NAN, 0.0}, 0.1, 0.1));
  EXPECT_FALSE(sim->addDrop({0.0, 0.0}, INFINITY, 0.1));
  EXPECT_FALSE(sim->addDrop({0.0, 0.0}, 0.1, -INFINITY));
  EXPECT_FALSE(sim->moveSphere({0.0, NAN, 0.0}, {0.0, 0.0, 0.0}, 0.5));
  EXPECT_FALSE(sim->moveSphere({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, -1.0));
  for (const glm::vec4& t : sim->read()) ASSERT_EQ(t, glm::vec4(0.0f));  // refused: no change
  EXPECT_TRUE(sim->addDrop({0.0, 0.0}, 1e30, 1e30));
  EXPECT_TRUE(sim->addDrop({1e300, -1e300}, 1e-30, -1e30));
  EXPECT_TRUE(sim->addDrop({0.01, 0.02}, 1e-9, 1e9));  // one texel, full strength: a spike
  EXPECT_TRUE(sim->moveSphere({0.0, 1e9, 0.0}, {0.1, -1e9, 0.2}, 1e9));
  EXPECT_TRUE(sim->moveSphere({0.1, -0.2, 0.0}, {-0.1, 0.1, 0.0}, 1e-12));
  for (int round = 0; round < 4; ++round) {
    sim->step(100);
    for (const glm::vec4& t : sim->read()) {
      ASSERT_TRUE(std::isfinite(t.x) && std::isfinite(t.y) && std::isfinite(t.z) &&
                  std::isfinite(t.w));
      ASSERT_LE(std::abs(t.z), float(desc.maxHeight));
    }
  }
}

// Moving the rectangle by whole texels keeps the water where it was in the world: texel (i, j)
// holds what (i + dx, j + dz) held, bit for bit, and what enters is at rest.
TEST_F(RippleSimulationTest, ShiftKeepsTheWaterInPlace) {
  RippleDesc desc;
  desc.resolution = 32;
  desc.size = {4.0, 4.0};
  auto sim = make(desc);
  ASSERT_TRUE(sim);
  ASSERT_TRUE(sim->addDrop({0.3, -0.2}, 1.2, 0.05));
  sim->step(10);
  const std::vector<glm::vec4> before = sim->read();
  const glm::ivec2 by(3, -2);
  sim->shift(by);
  const std::vector<glm::vec4> after = sim->read();
  const int n = desc.resolution;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int fi = i + by.x, fj = j + by.y;
      const bool inside = fi >= 0 && fi < n && fj >= 0 && fj < n;
      const glm::vec4 was = inside ? before[size_t(fj * n + fi)] : glm::vec4(0.0f);
      const glm::vec4 now = after[size_t(j * n + i)];
      ASSERT_EQ(now.z, was.z) << i << "," << j;  // height
      ASSERT_EQ(now.w, was.w) << i << "," << j;  // velocity
    }
  }
  sim->shift({1000, 0});  // beyond the rectangle: all at rest
  for (const glm::vec4& t : sim->read()) ASSERT_EQ(t, glm::vec4(0.0f));
}

// An absorbing band lets a drop's ring leave: after the ring has crossed the rectangle twice,
// the waves left hold under 5 % of the energy (sum of (h - mean)^2) that reflecting walls keep
// (3.2 % measured: in 2D a wave leaves a slowly fading tail behind its front, which lingers
// inside). The mean is the drop's volume spread flat: the band damps motion, not a still level.
TEST_F(RippleSimulationTest, AbsorbingEdgeLetsWavesLeave) {
  RippleDesc desc;
  desc.resolution = 64;
  desc.size = {8.0, 8.0};
  desc.damping = 0.0;
  auto energyAfter = [&](double edge) {
    RippleDesc d = desc;
    d.absorbingEdge = edge;
    auto sim = make(d);
    EXPECT_TRUE(sim->addDrop({0.5, -0.3}, 0.6, 0.05));
    sim->step(8 * sim->stepsPerSecond());  // 8 s: 9.6 m at 1.2 m/s
    const std::vector<glm::vec4> texels = sim->read();
    const double mean = heightSum(texels) / double(texels.size());
    double energy = 0.0;
    for (const glm::vec4& t : texels) energy += (double(t.z) - mean) * (double(t.z) - mean);
    return energy;
  };
  const double walls = energyAfter(0.0), open = energyAfter(1.5);
  std::printf("energy after 8 s: %.4g with walls, %.4g with a 1.5 m absorbing band\n", walls, open);
  EXPECT_LT(open, 0.05 * walls);
}

TEST_F(RippleSimulationTest, RefusesOutOfRangeDescriptions) {
  std::string error;
  RippleDesc desc;
  desc.resolution = 8;
  EXPECT_FALSE(RippleSimulation::create(desc, error));
  EXPECT_NE(error.find("resolution"), std::string::npos) << error;
  desc = {};
  desc.size = {NAN, 1.0};
  EXPECT_FALSE(RippleSimulation::create(desc, error));
  EXPECT_NE(error.find("size"), std::string::npos) << error;
  desc = {};
  desc.waveSpeed = 0.0;
  EXPECT_FALSE(RippleSimulation::create(desc, error));
  EXPECT_NE(error.find("waveSpeed"), std::string::npos) << error;
  desc = {};
  desc.resolution = 2048;
  desc.size = {0.05, 0.05};
  desc.waveSpeed = 50.0;  // 4e6 steps a second
  EXPECT_FALSE(RippleSimulation::create(desc, error));
  EXPECT_NE(error.find("steps a second"), std::string::npos) << error;
}

}  // namespace
