// Local lights' object caustics against what optics says they must be: the inverse
// square through a thin pane, a spot cone's edge, a glass sphere's focus and flux.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <postfx/object_caustics/postfx_object_caustics.h>

#include "gl_fixture.h"
#include "postfx_object_caustics_lights_util.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

glm::dmat4 scaled(const glm::dvec3& centre, const glm::dvec3& scale) {
  glm::dmat4 m = translation(centre);
  m[0][0] = scale.x;
  m[1][1] = scale.y;
  m[2][2] = scale.z;
  return m;
}

postfx::CasterMaterial thinGlass() {
  postfx::CasterMaterial m;
  m.ior = 1.5f;
  m.thinWalled = true;
  return m;
}

// Dispatches the light alone (no sun) and reads its map back.
LightMap runLight(postfx::Context& fx, const ObjectHost& host, const postfx::CasterMesh& caster,
                  const postfx::LocalLight& light, const postfx::ObjectCausticsSettings& s) {
  EXPECT_EQ(postfx::dispatch(fx, lightsOnlyFrame(host, &caster, 1, &light, 1, s)), Result::Ok)
      << postfx::lastError(&fx);
  EXPECT_EQ(postfx::stats(fx).lightSkip[0], postfx::LightSkip::None);
  return LightMap(postfx::testing::lightCausticMap(fx), light.position);
}

// Mean green value over the texels within `radius` texels of the map's centre.
double centreValue(const LightMap& map, int radius) {
  double sum = 0.0;
  int n = 0;
  const int c = map.size / 2;
  for (int y = c - radius; y < c + radius; ++y)
    for (int x = c - radius; x < c + radius; ++x) {
      sum += map.value[size_t(y) * map.size + x].g;
      ++n;
    }
  return sum / n;
}

class PostfxObjectCausticsLightsTest : public testsupport::GlTest {};

// A thin-walled pane between a spot light and a plane lets the light through unbent, less the
// Fresnel reflection of its two faces: on the axis the irradiance is I * T / D^2 at any
// distance D, the same geometry scaled from 1 to 10 m.
TEST_F(PostfxObjectCausticsLightsTest, ThinPaneGivesTheInverseSquare) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh cube = makeCubeMesh(1.0);
  auto fx = makeLightContext(1);
  const postfx::ObjectCausticsSettings s = sizedSettings(128, 256);
  const double t = 1.0 - double(shared::fresnelDielectric(1.0f, 1.5f));
  const double transmitted = t * t;
  for (double d : {1.0, 2.0, 5.0, 10.0}) {
    SCOPED_TRACE(d);
    const glm::dvec3 position(0.0, d, 0.0), down(0.0, -1.0, 0.0);
    LightReceiverMap receivers(position, down, 40.0, 0.0, 512);
    postfx::LocalLight light =
        makeLight(postfx::LocalLightType::Spot, position, down, receivers.desc());
    light.coneAngleDegrees = 30.0f;
    light.coneSoftness = 0.0f;
    const postfx::CasterMesh pane =
        cube.caster(scaled({0.0, 0.5 * d, 0.0}, {0.4 * d, 0.002 * d, 0.4 * d}), thinGlass());
    const LightMap map = runLight(*fx, host, pane, light, s);
    ASSERT_TRUE(map.allFinite());
    const double e = centreValue(map, 4);
    std::printf("D %5.1f m: E * D^2 / T = %.5f\n", d, e * d * d / transmitted);
    EXPECT_NEAR(e * d * d / transmitted, 1.0, 0.01);
  }
}

// Under water the same pane's light is absorbed along the whole path, light to pane and pane to
// receiver (Beer-Lambert, the water's absorption per channel), and the pane's Fresnel loss is
// that of glass against water.
TEST_F(PostfxObjectCausticsLightsTest, UnderWaterTheLightIsAbsorbedAlongItsPath) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh cube = makeCubeMesh(1.0);
  auto fx = makeLightContext(1);
  const postfx::ObjectCausticsSettings s = sizedSettings(128, 256);
  for (double d : {2.0, 5.0}) {
    SCOPED_TRACE(d);
    const glm::dvec3 position(0.0, d, 0.0), down(0.0, -1.0, 0.0);
    LightReceiverMap receivers(position, down, 40.0, 0.0, 512);
    postfx::LocalLight light =
        makeLight(postfx::LocalLightType::Spot, position, down, receivers.desc());
    light.coneAngleDegrees = 30.0f;
    const postfx::CasterMesh pane =
        cube.caster(scaled({0.0, 0.5 * d, 0.0}, {0.4 * d, 0.002 * d, 0.4 * d}), thinGlass());
    postfx::FrameDesc frame = lightsOnlyFrame(host, &pane, 1, &light, 1, s);
    frame.water.level = d + 1.0;  // everything under water
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    ASSERT_EQ(postfx::stats(*fx).lightSkip[0], postfx::LightSkip::None);
    const LightMap map(postfx::testing::lightCausticMap(*fx), position);
    const double t = 1.0 - double(shared::fresnelDielectric(1.0f, 1.5f / frame.water.ior));
    const glm::dvec3 expected = t * t * glm::exp(-glm::dvec3(frame.water.absorption) * d);
    double measured[3] = {};
    const int c = map.size / 2;
    for (int y = c - 2; y < c + 2; ++y)
      for (int x = c - 2; x < c + 2; ++x)
        for (int ch = 0; ch < 3; ++ch)
          measured[ch] += map.value[size_t(y) * map.size + x][ch] / 16.0;
    for (int ch = 0; ch < 3; ++ch) {
      std::printf("D %.0f m, channel %d: E * D^2 / I = %.5f, expected %.5f\n", d, ch,
                  measured[ch] * d * d, expected[ch]);
      EXPECT_NEAR(measured[ch] * d * d / expected[ch], 1.0, 0.01) << ch;
    }
  }
}

// A spot's cone cuts the light where its angles say: with a hard edge the irradiance halves at
// the outer half-angle, with softness s at the middle of the fade ((1 - s/2) of it); nothing
// lands beyond the edge (past the splat's reach).
TEST_F(PostfxObjectCausticsLightsTest, SpotConeCutsTheLightWhereItSays) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh cube = makeCubeMesh(1.0);
  auto fx = makeLightContext(1);
  const postfx::ObjectCausticsSettings s = sizedSettings(128, 256);
  const double d = 3.0;
  const glm::dvec3 position(0.0, d, 0.0), down(0.0, -1.0, 0.0);
  LightReceiverMap receivers(position, down, 40.0, 0.0, 512);
  const postfx::CasterMesh pane =
      cube.caster(scaled({0.0, 0.5 * d, 0.0}, {0.4 * d, 0.002 * d, 0.4 * d}), thinGlass());
  for (float softness : {0.0f, 0.5f}) {
    SCOPED_TRACE(softness);
    postfx::LocalLight light =
        makeLight(postfx::LocalLightType::Spot, position, down, receivers.desc());
    light.coneAngleDegrees = 30.0f;
    light.coneSoftness = softness;
    const LightMap map = runLight(*fx, host, pane, light, s);
    ASSERT_TRUE(map.allFinite());
    const double onAxis = centreValue(map, 2);
    // Along the centre row, outward on both sides: where the irradiance falls through half of
    // the axis value (interpolated), as an angle from the axis.
    const int c = map.size / 2;
    const double expected = 15.0 * (1.0 - 0.5 * double(softness));
    for (int side : {-1, 1}) {
      double edgeAngle = -1.0;
      for (int i = 0; i < c - 1; ++i) {
        const int x0 = side > 0 ? c + i : c - 1 - i, x1 = x0 + side;
        const double v0 = map.value[size_t(c) * map.size + x0].g;
        const double v1 = map.value[size_t(c) * map.size + x1].g;
        if (v0 >= 0.5 * onAxis && v1 < 0.5 * onAxis) {
          const double f = (v0 - 0.5 * onAxis) / (v0 - v1);
          const glm::dvec3 dir = map.direction(x0 + 0.5 + f * side, c + 0.5);
          edgeAngle = glm::degrees(std::acos(-dir.y));
          break;
        }
      }
      std::printf("softness %.1f, side %+d: half irradiance at %.3f deg (expected %.3f)\n",
                  double(softness), side, edgeAngle, expected);
      EXPECT_NEAR(edgeAngle, expected, 0.02 * expected);
    }
    // Nothing beyond the outer edge and the splats' reach: the sprite's corner, 3 sigma along
    // both axes (sigma ~1.1 texels: the splat radius widened by the ray lattice), 4.7 texels.
    double outside = 0.0, inside = 0.0;
    for (int y = 0; y < map.size; ++y)
      for (int x = 0; x < map.size; ++x) {
        const glm::dvec3 dir = map.direction(x + 0.5, y + 0.5);
        const double angle = glm::degrees(std::acos(-dir.y));
        const double texelDegrees = glm::degrees(
            std::acos(glm::dot(map.direction(x + 0.5, y + 0.5), map.direction(x + 5.5, y + 0.5))));
        const double g = map.value[size_t(y) * map.size + x].g;
        (angle > 15.0 + texelDegrees ? outside : inside) += g;
      }
    EXPECT_GT(inside, 0.0);
    EXPECT_EQ(outside, 0.0) << "light outside the cone";
  }
}

// The glass ball lens of the seeds: a sphere (R = 0.25 m, IOR 1.5) lit by a narrow spot 2 m from
// its centre focuses where the thick-lens equation puts it: f = n R / (2 (n - 1)) from the
// centre, 1/u + 1/v = 1/f. The aperture is kept paraxial (the cone lights 0.15 R of the
// sphere) so that spherical aberration moves the best focus by ~1 % (0.3 R: 3.3 %).
TEST_F(PostfxObjectCausticsLightsTest, GlassSphereFocusesAtTheThickLensPosition) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(0.25, 96, 48);
  auto fx = makeLightContext(1);
  postfx::ObjectCausticsSettings s = sizedSettings(256, 512);
  s.iterations = 3;
  const double radius = 0.25, ior = 1.5, u = 2.0;
  const double f = ior * radius / (2.0 * (ior - 1.0));
  const double v = 1.0 / (1.0 / f - 1.0 / u);
  postfx::CasterMaterial glass;
  glass.ior = float(ior);
  std::vector<double> scale, rms;
  for (double k = 0.88; k < 1.121; k += 0.04) {
    const double centreY = k * v;  // the receiver plane is y = 0
    const glm::dvec3 position(0.0, centreY + u, 0.0), down(0.0, -1.0, 0.0);
    LightReceiverMap receivers(position, down, 10.0, 0.0, 512);
    postfx::LocalLight light =
        makeLight(postfx::LocalLightType::Spot, position, down, receivers.desc());
    light.coneAngleDegrees = float(2.0 * glm::degrees(std::atan(0.15 * radius / (u - radius))));
    light.coneSoftness = 0.0f;
    const postfx::CasterMesh caster = mesh.caster(translation({0.0, centreY, 0.0}), glass);
    const LightMap map = runLight(*fx, host, caster, light, s);
    ASSERT_TRUE(map.allFinite());
    glm::dvec3 centroid;
    double r = 0.0;
    map.spotOnPlane(0.0, centroid, r);
    std::printf("plane at %.3f v: spot centroid (%.5f, %.5f), RMS radius %.5f m\n", k, centroid.x,
                centroid.z, r);
    EXPECT_LT(glm::length(glm::dvec2(centroid.x, centroid.z)), 0.002) << "on the axis";
    scale.push_back(k);
    rms.push_back(r);
  }
  // The smallest spot, refined by a parabola through it and its neighbours.
  size_t best = 0;
  for (size_t i = 1; i < rms.size(); ++i)
    if (rms[i] < rms[best]) best = i;
  ASSERT_GT(best, 0u) << "the focus lies inside the scanned range";
  ASSERT_LT(best, rms.size() - 1);
  const double a = rms[best - 1], b = rms[best], c = rms[best + 1];
  const double step = scale[best + 1] - scale[best];
  const double focus = scale[best] + 0.5 * step * (a - c) / (a - 2.0 * b + c);
  std::printf("best focus at %.4f of the thick-lens distance v = %.4f m from the centre\n", focus,
              v);
  EXPECT_NEAR(focus, 1.0, 0.025);
}

// A point light 2 m from a glass sphere: the flux that lands is the intensity times the
// sphere's solid angle, less the Fresnel reflection at both surfaces and the absorption along
// each chord (exactly integrated over the incidence angle), per colour channel.
TEST_F(PostfxObjectCausticsLightsTest, SphereFluxMatchesFresnelAndAbsorption) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(0.25, 128, 64);
  auto fx = makeLightContext(1);
  const postfx::ObjectCausticsSettings s = sizedSettings(256, 512);
  const double radius = 0.25, ior = 1.5, u = 2.0;
  const glm::dvec3 absorption(0.8, 0.3, 0.05);
  postfx::CasterMaterial glass;
  glass.ior = float(ior);
  glass.absorption = glm::vec3(absorption);
  const double centreY = radius + 0.1;
  const glm::dvec3 position(0.0, centreY + u, 0.0), down(0.0, -1.0, 0.0);
  LightReceiverMap receivers(position, down, 30.0, 0.0, 1024);
  const postfx::LocalLight light =
      makeLight(postfx::LocalLightType::Point, position, down, receivers.desc());
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, centreY, 0.0}), glass);
  const LightMap map = runLight(*fx, host, caster, light, s);
  ASSERT_TRUE(map.allFinite());
  // Exact: over the angle alpha from the centre's direction, incidence sin(i) = u sin(alpha) / R,
  // the same Fresnel loss where the ray leaves (the chord is symmetric), chord 2 R cos(t).
  const double alphaMax = std::asin(radius / u);
  glm::dvec3 expected(0.0);
  const int steps = 20000;
  for (int k = 0; k < steps; ++k) {
    const double alpha = (k + 0.5) / steps * alphaMax;
    const double sinI = std::min(u * std::sin(alpha) / radius, 1.0);
    const double cosI = std::sqrt(1.0 - sinI * sinI);
    const double sinT = sinI / ior, cosT = std::sqrt(1.0 - sinT * sinT);
    const double t = 1.0 - double(shared::fresnelDielectric(float(cosI), float(ior)));
    const glm::dvec3 kept = t * t * glm::exp(-absorption * (2.0 * radius * cosT));
    expected += kept * (2.0 * kPi * std::sin(alpha) * alphaMax / steps);
  }
  const glm::dvec3 flux = map.fluxOnPlane(0.0);
  const double solidAngle = 2.0 * kPi * (1.0 - std::cos(alphaMax));
  std::printf("solid angle %.6f sr; flux GPU (%.6f %.6f %.6f), exact (%.6f %.6f %.6f)\n",
              solidAngle, flux.r, flux.g, flux.b, expected.r, expected.g, expected.b);
  for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(flux[ch] / expected[ch], 1.0, 0.03) << ch;
}

}  // namespace
