// The object-caustics reference for point and spot lights on cases with known answers: the ball
// lens's paraxial image, the inverse-square and cosine laws, the spot cone's edge, and the flux
// through a glass sphere against the exact Fresnel/absorption integral over its solid angle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "object_caustics_light_metrics.h"
#include "object_caustics_local_light.h"
#include "object_caustics_metrics.h"
#include "object_caustics_optics.h"

namespace {

using namespace ocean::reference;

constexpr double kPi = 3.141592653589793;

SphereCaster glassBall(const glm::dvec3& centre, double radius) {
  SphereCaster s;
  s.centre = centre;
  s.radius = radius;
  s.ior = 1.5;
  return s;
}

// Ball lens (thick lens, principal planes through the centre): f = n R / (2 (n - 1)), and
// 1/s + 1/s' = 1/f with s, s' from the centre.
double paraxialImage(double ior, double radius, double s) {
  const double f = ior * radius / (2.0 * (ior - 1.0));
  return 1.0 / (1.0 / f - 1.0 / s);
}

TEST(ReferenceLocalLight, BallLensImagesThePointLightWhereTheLensFormulaSays) {
  const double radius = 0.25, s = 2.0;
  const SphereCaster ball = glassBall(glm::dvec3(0.0), radius);
  const glm::dvec3 light(0.0, s, 0.0);
  const double image = paraxialImage(ball.ior, radius, s);
  // A ray at impact height h from the axis (h = s sin(angle)).
  auto crossing = [&](double h) { return axisCrossingFromCentre(ball, light, std::asin(h / s)); };
  const double paraxial = crossing(1e-3 * radius);
  // Third-order spherical aberration: the crossing moves toward the lens as h^2.
  const double lsa1 = image - crossing(0.05 * radius), lsa2 = image - crossing(0.1 * radius);
  const double marginal = crossing(0.95 * radius);
  std::printf(
      "ball lens R %.2f n %.2f, light %.1f m from the centre: image %.6f m (lens formula), "
      "traced paraxial %.6f, h = 0.05/0.1 R short by %.3g/%.3g m (ratio %.3f, third order: 4), "
      "marginal (0.95 R) %.4f\n",
      radius, ball.ior, s, image, paraxial, lsa1, lsa2, lsa2 / lsa1, marginal);
  EXPECT_NEAR(paraxial / image, 1.0, 1e-5);
  EXPECT_GT(lsa1, 0.0);
  EXPECT_NEAR(lsa2 / lsa1, 4.0, 0.05);
  EXPECT_GT(marginal, 0.0);
  EXPECT_LT(marginal, image);
}

TEST(ReferenceLocalLight, BinnedCausticPeaksWhereTheAxisMeetsTheFloor) {
  // The light 2 m from a 0.25 m ball, 30 degrees off the vertical; the floor cuts the axis just
  // short of the paraxial image, inside the axial caustic (between the marginal and paraxial
  // foci), where the traced light peaks on the axis.
  const double radius = 0.25, s = 2.0;
  const double image = paraxialImage(1.5, radius, s);
  const double tilt = 30.0 * kPi / 180.0;
  const glm::dvec3 axis(std::sin(tilt), -std::cos(tilt), 0.0);
  const double toFloor = 0.98 * image;
  const glm::dvec3 centre = glm::dvec3(0.0) - axis * toFloor;  // the axis meets y = 0 at 0
  const SphereCaster ball = glassBall(centre, radius);
  LocalLightSource light;
  light.position = centre - axis * s;
  const ReceiverBins bins = floorBins(glm::dvec3(0.0), 0.0, 0.2, 200);  // 1 mm bins
  const LocalCausticReference ref = traceSphereFromLight(ball, light, bins, glm::dvec3(0.0), 1500);
  const glm::dvec3 focus = binPoint(bins, focusTexel(ref.irradiance, bins.size, 3));
  std::printf("floor cuts the axis at (0, 0, 0): binned peak at (%.5f, %.5f, %.5f) m, %.3f %% R\n",
              focus.x, focus.y, focus.z, 100.0 * glm::length(focus) / radius);
  EXPECT_LT(glm::length(focus), 0.02 * radius);
}

TEST(ReferenceLocalLight, InverseSquareAndCosineLawsHold) {
  LocalLightSource light;
  light.position = {0.3, -0.2, 1.1};
  light.intensity = {2.0, 1.0, 0.5};
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.2, -1.0, 0.4));
  const double half = 0.05;  // 10 cm bin
  double lo = 1e30, hi = 0.0, worstExact = 0.0;
  for (int r = 1; r <= 10; ++r) {
    const ReceiverBins bin = facingBins(light.position, axis, r, 2.0 * half, 1);
    const LocalCausticReference ref = traceDirectLight(light, bin, glm::dvec3(0.0), 300);
    const double e = ref.irradiance[0].g / light.intensity.g;
    // The solid angle of the square exactly: the bin's mean irradiance is I Omega / area.
    const double omega = 4.0 * std::atan(half * half / (r * std::sqrt(r * r + 2.0 * half * half)));
    worstExact = std::max(worstExact, std::abs(e / (omega / (4.0 * half * half)) - 1.0));
    lo = std::min(lo, e * r * r);
    hi = std::max(hi, e * r * r);
    EXPECT_NEAR(ref.irradiance[0].r / ref.irradiance[0].g, 2.0, 1e-12);
  }
  std::printf("facing bin 1..10 m: E r^2 / I in [%.5f, %.5f]; worst vs exact solid angle %.2g\n",
              lo, hi, worstExact);
  EXPECT_LT(hi / lo - 1.0, 0.01);
  EXPECT_LT(worstExact, 1e-3);

  // On a floor 2 m below the light, 1.5 m to the side: E = I h / d^3.
  const ReceiverBins floor =
      floorBins(light.position + glm::dvec3(1.5, 0.0, 0.0), light.position.y - 2.0, 0.02, 1);
  const double e = traceDirectLight(light, floor, glm::dvec3(0.0), 300).irradiance[0].g;
  const double expected = light.intensity.g * 2.0 / std::pow(2.0 * 2.0 + 1.5 * 1.5, 1.5);
  std::printf("floor bin 2.5 m from the light at 37 degrees: E %.6f, I h / d^3 %.6f\n", e,
              expected);
  EXPECT_NEAR(e / expected, 1.0, 1e-3);

  // Through water: Beer-Lambert along the path.
  const glm::dvec3 sigma(0.35, 0.06, 0.02);
  for (int r : {1, 4, 10}) {
    const ReceiverBins bin = facingBins(light.position, axis, r, 0.02, 1);
    const glm::dvec3 wet = traceDirectLight(light, bin, sigma, 100).irradiance[0];
    const glm::dvec3 dry = traceDirectLight(light, bin, glm::dvec3(0.0), 100).irradiance[0];
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(wet[c] / dry[c], std::exp(-sigma[c] * r), 1e-4 * std::exp(-sigma[c] * r))
          << r << " m, channel " << c;
  }
}

// The radius (m, from the point below the light) where the floor's light, divided by the point
// light's own I h / d^3, falls through 1/2: the cone's edge as traced.
double tracedConeEdge(const LocalLightSource& light, double height, double guess) {
  const double side = 0.3;
  const int size = 300;  // 1 mm bins
  const ReceiverBins bins = floorBins(light.position + glm::dvec3(guess, 0.0, 0.0),
                                      light.position.y - height, side, size);
  const LocalCausticReference ref = traceDirectLight(light, bins, glm::dvec3(0.0), 1200);
  // Radial profile in 2 mm rings of the cone factor.
  const double ring = 0.002;
  std::vector<double> sum(400, 0.0), count(400, 0.0);
  const double r0 = guess - 0.4 * side;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const glm::dvec3 p = binPoint(bins, glm::dvec2(i + 0.5, j + 0.5));
      const glm::dvec3 d = p - light.position;
      const double r = std::hypot(d.x, d.z);
      const int k = int((r - r0) / ring);
      if (k < 0 || k >= 400) continue;
      const double law = light.intensity.g * height / std::pow(glm::dot(d, d), 1.5);
      sum[k] += ref.irradiance[size_t(j) * size + i].g / law;
      count[k] += 1.0;
    }
  double previous = -1.0, previousR = 0.0;
  for (int k = 0; k < 400; ++k) {
    if (count[k] < 20.0) continue;
    const double v = sum[k] / count[k], r = r0 + (k + 0.5) * ring;
    if (previous >= 0.5 && v < 0.5)
      return previousR + (previous - 0.5) / (previous - v) * (r - previousR);
    previous = v;
    previousR = r;
  }
  return -1.0;
}

TEST(ReferenceLocalLight, SpotConeEdgeLiesWhereItsAngleSays) {
  LocalLightSource spot;
  spot.spot = true;
  spot.position = {0.0, 2.0, 0.0};
  spot.direction = {0.0, -1.0, 0.0};
  spot.coneAngleDegrees = 60.0;
  const double height = 2.0;
  // Hard edge at the half-angle; a soft one halfway through its smoothstep.
  spot.coneSoftness = 0.0;
  const double hard = height * std::tan(30.0 * kPi / 180.0);
  const double tracedHard = tracedConeEdge(spot, height, hard);
  spot.coneSoftness = 0.2;
  const double soft = height * std::tan(27.0 * kPi / 180.0);
  const double tracedSoft = tracedConeEdge(spot, height, soft);
  std::printf(
      "cone 60 deg from 2 m: edge %.4f m (half-angle %.4f), soft 0.2 half-way %.4f m "
      "(27 deg %.4f)\n",
      tracedHard, hard, tracedSoft, soft);
  EXPECT_NEAR(tracedHard, hard, 0.002);
  EXPECT_NEAR(tracedSoft, soft, 0.002);
}

// The exact flux through the sphere: I times the integral over the cap it subtends of
// (1 - F)^2 exp(-absorption chord), where a ray at impact parameter b meets the surface at
// sin(i) = b / R, refracts to sin(t) = sin(i) / n and crosses the chord 2 R cos(t); the exit
// Fresnel equals the entry's (the internal angle is t again). Simpson over the angle from the
// axis.
glm::dvec3 exactFluxThroughSphere(const SphereCaster& s, double distance) {
  const double thetaMax = std::asin(s.radius / distance);
  const int n = 200000;
  glm::dvec3 sum(0.0);
  for (int k = 0; k <= n; ++k) {
    const double theta = thetaMax * k / n;
    const double sinI = std::min(1.0, distance * std::sin(theta) / s.radius);
    const double cosI = std::sqrt(1.0 - sinI * sinI);
    const double sinT = sinI / s.ior, cosT = std::sqrt(1.0 - sinT * sinT);
    const double t = 1.0 - fresnel(cosI, s.ior);
    const glm::dvec3 f =
        t * t * glm::exp(-s.absorption * (2.0 * s.radius * cosT)) * 2.0 * kPi * std::sin(theta);
    sum += f * double(k == 0 || k == n ? 1 : (k % 2 ? 4 : 2));
  }
  return sum * (thetaMax / n / 3.0);
}

TEST(ReferenceLocalLight, FluxThroughTheSphereIsFresnelAndAbsorptionOverItsSolidAngle) {
  SphereCaster ball = glassBall({0.1, 0.2, -0.3}, 0.3);
  ball.absorption = {0.2, 1.0, 3.0};
  LocalLightSource light;
  light.position = ball.centre + glm::dvec3(0.5, 1.9, 0.4);
  light.intensity = {1.0, 2.0, 4.0};
  const double distance = glm::length(ball.centre - light.position);
  const ReceiverBins bins = floorBins(ball.centre, -1.0, 2.0, 50);
  const LocalCausticReference ref = traceSphereFromLight(ball, light, bins, glm::dvec3(0.0), 800);
  const glm::dvec3 exact = light.intensity * exactFluxThroughSphere(ball, distance);
  std::printf(
      "flux through the sphere: traced (%.6f %.6f %.6f), exact (%.6f %.6f %.6f); emitted into "
      "its solid angle %.6f\n",
      ref.fluxLeaving.r, ref.fluxLeaving.g, ref.fluxLeaving.b, exact.r, exact.g, exact.b,
      ref.fluxEmitted.g);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ref.fluxLeaving[c] / exact[c], 1.0, 0.005) << c;
  // With no water every ray leaving downward lands on the floor, in the bins or beside them.
  const glm::dvec3 landed = ref.fluxInBins + ref.fluxOutside;
  EXPECT_LE(landed.g, ref.fluxLeaving.g * (1.0 + 1e-12));
  EXPECT_GT(landed.g, 0.99 * ref.fluxLeaving.g);

  // IOR 1, clear: no Fresnel, no bending: exactly the solid angle, 2 pi (1 - cos).
  SphereCaster clear = ball;
  clear.ior = 1.0;
  clear.absorption = glm::dvec3(0.0);
  const double omega = 2.0 * kPi * (1.0 - std::sqrt(1.0 - std::pow(ball.radius / distance, 2.0)));
  const LocalCausticReference open = traceSphereFromLight(clear, light, bins, glm::dvec3(0.0), 200);
  EXPECT_NEAR(open.fluxLeaving.g / (light.intensity.g * omega), 1.0, 1e-12);
}

TEST(ReferenceLocalLight, WaterAbsorbsAlongBothLegs) {
  // IOR 1 clear sphere: the rays go straight, so the flux on a plane facing the light at D is
  // I times the integral over the sphere's cap of exp(-sigma (D / cos(theta) - chord)): the water
  // absorbs along the path but not along the chord, where the caster displaces it.
  SphereCaster clear = glassBall({0.0, 1.0, 0.0}, 0.2);
  clear.ior = 1.0;
  LocalLightSource light;
  light.position = {0.0, 2.5, 0.0};
  const glm::dvec3 sigma(0.35, 0.06, 0.02);
  const double plane = 3.0;  // m from the light
  const ReceiverBins bins = facingBins(light.position, {0.0, -1.0, 0.0}, plane, 2.0, 40);
  const LocalCausticReference ref = traceSphereFromLight(clear, light, bins, sigma, 600);
  const double thetaMax = std::asin(0.2 / 1.5);
  auto chord = [](double theta) {
    const double b = 1.5 * std::sin(theta);
    return 2.0 * std::sqrt(std::max(0.0, 0.2 * 0.2 - b * b));
  };
  for (int c = 0; c < 3; ++c) {
    const int n = 20000;
    double sum = 0.0;
    for (int k = 0; k <= n; ++k) {
      const double t = thetaMax * k / n;
      sum += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * 2.0 * kPi * std::sin(t) *
             std::exp(-sigma[c] * (plane / std::cos(t) - chord(t)));
    }
    const double exact = sum * thetaMax / n / 3.0;
    EXPECT_NEAR(ref.fluxInBins[c] / exact, 1.0, 1e-4) << "channel " << c;
  }
}

TEST(ReferenceLocalLight, LightAtTheCentreLeavesThroughOneSurface) {
  SphereCaster ball = glassBall({0.0, 1.0, 0.0}, 0.5);
  ball.absorption = {0.1, 0.5, 2.0};
  LocalLightSource light;
  light.position = ball.centre;
  const ReceiverBins bins = floorBins(ball.centre, 0.0, 4.0, 40);
  const LocalCausticReference ref = traceSphereFromLight(ball, light, bins, glm::dvec3(0.0), 200);
  const double r0 = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);
  EXPECT_NEAR(ref.solidAngle, 4.0 * kPi, 1e-12);
  for (int c = 0; c < 3; ++c) {
    const double exact = 4.0 * kPi * (1.0 - r0) * std::exp(-ball.absorption[c] * 0.5);
    EXPECT_NEAR(ref.fluxLeaving[c] / exact, 1.0, 1e-9) << c;
  }
  for (const glm::dvec3& v : ref.irradiance) ASSERT_TRUE(std::isfinite(v.g));
}

// The plugin's light map placed on a plane: a synthetic map of the unobstructed light (E = 1/r^2
// facing the light, r to the floor along each texel) from a light 2 m above a floor, seen
// through a square frustum of half-angle 35 degrees tilted 20 degrees, lands as the traced
// direct light, and its flux is the frustum's solid angle.
TEST(ReferenceLocalLight, LightMapOnAPlaneKeepsFluxAndTheCosineLaw) {
  const glm::dvec3 light(0.2, 2.0, -0.1);
  const double half = 35.0 * kPi / 180.0, tilt = 20.0 * kPi / 180.0;
  const glm::dvec3 axis(std::sin(tilt), -std::cos(tilt), 0.0);
  const glm::dmat4 clip = glm::perspectiveRH_ZO(2.0 * half, 1.0, 0.1, 50.0) *
                          glm::lookAt(light, light + axis, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 inverse = glm::inverse(clip);
  const int size = 128;
  std::vector<glm::dvec3> map(size_t(size) * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec2 ndc = (glm::dvec2(x, y) + 0.5) / double(size) * 2.0 - 1.0;
      const glm::dvec4 far = inverse * glm::dvec4(ndc, 1.0, 1.0);
      const glm::dvec3 d = glm::normalize(glm::dvec3(far) / far.w - light);
      const double r = light.y / -d.y;
      map[size_t(y) * size + x] = glm::dvec3(1.0 / (r * r));
    }
  const ReceiverBins bins = floorBins(light, 0.0, 8.0, 40);  // 20 cm bins
  // 16^2 parts a texel: a bin edge cuts a texel (2-8 cm here) within 1/16 of it.
  const LightMapOnPlane placed = lightMapOnBins(map, size, clip, light, bins, 16);
  const double omega = 4.0 * std::asin(std::pow(std::sin(half), 2.0));
  const double flux = placed.fluxInBins.g + placed.fluxOutside.g;
  // Against the direct light traced into the same bins, where the frustum covers a bin whole.
  LocalLightSource source;
  source.position = light;
  const LocalCausticReference direct = traceDirectLight(source, bins, glm::dvec3(0.0), 800);
  double worst = 0.0, sum = 0.0;
  int compared = 0;
  for (int j = 0; j < bins.size; ++j)
    for (int i = 0; i < bins.size; ++i) {
      bool inside = true;
      for (int c = 0; c < 4; ++c) {
        const glm::dvec3 p = binPoint(bins, glm::dvec2(i + (c & 1), j + (c >> 1)));
        const glm::dvec4 q = clip * glm::dvec4(p, 1.0);
        inside = inside && std::abs(q.x / q.w) < 0.98 && std::abs(q.y / q.w) < 0.98;
      }
      if (!inside) continue;
      const size_t k = size_t(j) * bins.size + i;
      const double error = placed.irradiance[k].g / direct.irradiance[k].g - 1.0;
      worst = std::max(worst, std::abs(error));
      sum += error;
      ++compared;
    }
  std::printf(
      "light map on a floor: flux %.6f sr (frustum %.6f), %d bins within %.3g of traced (mean "
      "error "
      "%+.3g)\n",
      flux, omega, compared, worst, sum / compared);
  EXPECT_NEAR(flux / omega, 1.0, 1e-3);
  EXPECT_GT(compared, 100);
  // A bin's edges cut the parts of texels (up to 8 cm / 16 on the floor at 55 degrees from the
  // vertical) where they fall: up to +-2.5 % for a 20 cm bin, with no bias over the bins.
  EXPECT_LT(worst, 0.03);
  EXPECT_LT(std::abs(sum / compared), 0.002);
}

// The ring's reflection from a point light far away is the sun's: E d^2 from a light 1e4 m off
// along the sun's direction carries the flux the sun's reference (irradiance 1) does.
TEST(ReferenceLocalLight, RingLitFromAfarReflectsWhatTheSunDoes) {
  RingCaster ring;
  ring.base = {0.1, 0.0, -0.2};
  ring.f0 = {0.9, 0.8, 0.6};
  const double zenith = 60.0 * kPi / 180.0;
  const glm::dvec3 towardSun(std::sin(zenith), std::cos(zenith), 0.0);
  // The sun's reference bins perpendicular to it; only the total flux is compared.
  postfx::ObjectCausticMap map;
  map.size = 64;
  const glm::dvec3 u = glm::normalize(glm::cross(glm::dvec3(0.0, 0.0, 1.0), -towardSun));
  map.axisU = u * 8.0;
  map.axisV = glm::cross(-towardSun, u) * 8.0;
  map.direction = -towardSun;
  map.origin = ring.base - 0.5 * (map.axisU + map.axisV);
  const CausticReference sun = traceRingReference(ring, towardSun, -0.5, map, 1200);
  LocalLightSource light;
  const double d = 1e4;
  light.position = ring.base + glm::dvec3(0.0, 0.5 * ring.height, 0.0) + towardSun * d;
  const ReceiverBins floor = floorBins(ring.base, -0.5, 8.0, 64);
  const LocalCausticReference far = traceRingFromLight(ring, light, floor, glm::dvec3(0.0), 1200);
  const glm::dvec3 sunFlux = sun.fluxInMap + sun.fluxOutside;
  const glm::dvec3 lightFlux = (far.fluxInBins + far.fluxOutside) * (d * d);
  std::printf(
      "ring: reflected flux, sun (%.5f %.5f %.5f) m^2, light 1e4 m off x d^2 (%.5f %.5f "
      "%.5f)\n",
      sunFlux.r, sunFlux.g, sunFlux.b, lightFlux.r, lightFlux.g, lightFlux.b);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(lightFlux[c] / sunFlux[c], 1.0, 0.005) << c;
  // Below the ring's top the light is refused: nothing traced.
  light.position.y = 0.1;
  EXPECT_EQ(traceRingFromLight(ring, light, floor, glm::dvec3(0.0), 10).fluxLeaving,
            glm::dvec3(0.0));
}

}  // namespace
