// The object-caustics reference and the report's binning, on cases with known answers: an IOR 1
// sphere only refills its own shadow (irradiance exactly 1 on the disc, flux pi R^2), and the
// resampling of a map onto bins that its texels do not line up with keeps constants and flux.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "object_caustics_metrics.h"
#include "object_caustics_reference.h"

namespace {

using namespace ocean::reference;

constexpr double kPi = 3.141592653589793;

// A 2 m map of 100 texels (2 cm) looking straight down, its corner off any bin boundary.
postfx::ObjectCausticMap straightDownMap() {
  postfx::ObjectCausticMap map;
  map.size = 100;
  map.origin = {-1.013, 3.0, -0.987};
  map.axisU = {2.0, 0.0, 0.0};
  map.axisV = {0.0, 0.0, 2.0};
  map.direction = {0.0, -1.0, 0.0};
  return map;
}

TEST(ReferenceObjectCaustics, ResamplingKeepsConstantsAndFlux) {
  const postfx::ObjectCausticMap map = straightDownMap();
  // 7 bins of 1/7 m (7.14 texels each) inside the map: no texel edge meets a bin edge.
  const postfx::ObjectCausticMap bins = binGrid(map, {0.05, 0.0, -0.03}, 1.0, 7);
  const std::vector<glm::dvec3> constant(size_t(map.size) * map.size, glm::dvec3(3.0));
  double worst = 0.0;
  for (double v : resampleToBins(constant, map, bins)) worst = std::max(worst, std::abs(v - 3.0));
  // One bright texel astride bin edges: its flux lands in the bins by overlap, all of it.
  std::vector<glm::dvec3> dot(size_t(map.size) * map.size, glm::dvec3(0.0));
  const int tx = 50, ty = 47;
  dot[size_t(ty) * map.size + tx] = glm::dvec3(10.0);
  const std::vector<double> spread = resampleToBins(dot, map, bins);
  const double binArea = (1.0 / 7.0) * (1.0 / 7.0), texelArea = 0.02 * 0.02;
  double flux = 0.0;
  int touched = 0;
  for (double v : spread) {
    flux += v * binArea;
    touched += v > 0.0 ? 1 : 0;
  }
  std::printf("constant map: worst bin error %.3g; one texel: flux %.9f of %.9f over %d bins\n",
              worst, flux, 10.0 * texelArea, touched);
  EXPECT_LT(worst, 1e-12);
  EXPECT_NEAR(flux, 10.0 * texelArea, 1e-12);
}

TEST(ReferenceObjectCaustics, IorOneSphereRefillsItsShadowExactly) {
  SphereCaster sphere;
  sphere.centre = {0.1, 1.5, -0.2};
  sphere.ior = 1.0;
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  postfx::ObjectCausticMap like = straightDownMap();
  // The bins' axes must be perpendicular to the light: build them from the light's own frame.
  const glm::dvec3 d = -sun;
  const glm::dvec3 u = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), d));
  like.axisU = u;
  like.axisV = glm::cross(d, u);
  like.direction = d;
  const postfx::ObjectCausticMap bins = binGrid(like, sphere.centre, 2.4, 24);  // 10 cm bins
  const CausticReference ref = traceSphereReference(sphere, sun, 0.0, bins, 600);
  double worstInside = 0.0, worstOutside = 0.0;
  const double b = 2.4 / 24;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 24; ++x) {
      // Bin centre's distance from the axis, in the light-perpendicular plane.
      const double r = std::hypot((x + 0.5) * b - 1.2, (y + 0.5) * b - 1.2);
      const double v = ref.irradiance[size_t(y) * 24 + x].g;
      if (r + b * 0.7072 < sphere.radius) worstInside = std::max(worstInside, std::abs(v - 1.0));
      if (r - b * 0.7072 > sphere.radius) worstOutside = std::max(worstOutside, std::abs(v));
    }
  const double flux = ref.fluxInMap.g + ref.fluxOutside.g;
  std::printf(
      "IOR 1: bins inside the disc within %.3g of 1, outside %.3g; flux %.5f (pi R^2 = %.5f), "
      "intercepted %.5f\n",
      worstInside, worstOutside, flux, kPi, ref.interceptedArea);
  // 600^2 stratified rays over 2.02^2 m^2: ~880 per 10 cm bin, one per stratum, so a bin's count
  // is exact but for the ~120 strata its edges cut, each in or out at random: a standard
  // deviation of sqrt(120 / 4) / 880 = 0.6 %; 4 % is beyond 6 sigma for the worst of ~350 bins.
  EXPECT_LT(worstInside, 0.04);
  EXPECT_EQ(worstOutside, 0.0);
  EXPECT_NEAR(flux, kPi, 2e-3 * kPi);
  EXPECT_NEAR(ref.interceptedArea, kPi, 2e-3 * kPi);
}

}  // namespace
