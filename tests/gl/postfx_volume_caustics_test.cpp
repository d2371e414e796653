// The volume caustics (Feature::VolumeCaustics): the light the glass sphere of
// ocean::validation::glassSphereInWater focuses, in-scattered in the water it crosses.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <volume_caustic_run.h>

#include "gl_fixture.h"

namespace {

using ocean::validation::VolumeCausticOptions;
using ocean::validation::VolumeCausticRun;
using ocean::validation::VolumeCausticScene;

constexpr double kPi = 3.14159265358979323846;

class PostfxVolumeCausticsTest : public testsupport::GlTest {};

std::vector<glm::dvec3> render(const VolumeCausticScene& scene,
                               const postfx::ObjectCausticsSettings& settings,
                               const VolumeCausticOptions& options) {
  VolumeCausticRun run;
  std::string error;
  EXPECT_TRUE(ocean::validation::runVolumeCaustic(scene, settings, options, run, error)) << error;
  return run.light;
}

// The volume's light alone: the frame with it less the frame without it (both add the same
// object caustics on the receivers).
std::vector<glm::dvec3> volumeLight(const VolumeCausticScene& scene,
                                    const postfx::ObjectCausticsSettings& settings) {
  VolumeCausticOptions off;
  off.volume = false;
  const std::vector<glm::dvec3> with = render(scene, settings, {});
  const std::vector<glm::dvec3> without = render(scene, settings, off);
  std::vector<glm::dvec3> out(with.size());
  for (size_t i = 0; i < out.size() && i < without.size(); ++i) out[i] = with[i] - without[i];
  return out;
}

// sum over pixels of L * Omega_pixel * t^2, t the distance to the plane z = sphere's z along the
// pixel's ray: the power per steradian the frame's light says reaches the camera, for light
// scattered near that plane (green).
double intensityTowardCamera(const VolumeCausticScene& scene,
                             const std::vector<glm::dvec3>& light) {
  const double focal = 1.0 / std::tan(30.0 * kPi / 180.0);
  const double aspect = double(scene.width) / scene.height;
  const double pixelArea = (2.0 * aspect / (focal * scene.width)) * (2.0 / (focal * scene.height));
  const double depth = -scene.sphere.centre.z;
  double sum = 0.0;
  for (int y = 0; y < scene.height; ++y)
    for (int x = 0; x < scene.width; ++x) {
      const double nx = ((x + 0.5) / scene.width * 2.0 - 1.0) * aspect / focal;
      const double ny = ((y + 0.5) / scene.height * 2.0 - 1.0) / focal;
      const double len2 = nx * nx + ny * ny + 1.0;
      const double omega = pixelArea / (len2 * std::sqrt(len2));
      sum += light[size_t(y) * scene.width + x].g * omega * depth * depth * len2;
    }
  return sum;
}

// A ball of IOR 1 in a thin medium lets every ray through straight from its lower half to the
// floor: the light they scatter toward the camera is phase * sigma_s * E * (the water volume
// they cross) = phase * sigma_s * E * (pi R^2 h - 2/3 pi R^3), h from the centre to the floor
// along the (vertical) sun.
VolumeCausticScene clearBallInThinWater() {
  VolumeCausticScene scene = ocean::validation::glassSphereInWater(320, 180);
  scene.sphere.ior = 1.0;
  scene.towardSun = {0.0, 1.0, 0.0};
  scene.scattering = glm::dvec3(1e-4);
  scene.absorption = glm::dvec3(0.0);
  scene.surfaceFade = 0.0;
  scene.depthFade = 0.0;
  scene.phase = 1.0;
  return scene;
}

double expectedIntensity(const VolumeCausticScene& scene, double irradianceAtBall) {
  const double r = scene.sphere.radius, h = scene.sphere.centre.y - scene.planeY;
  const double volume = kPi * r * r * h - 2.0 / 3.0 * kPi * r * r * r;
  return scene.phase * scene.scattering.g * irradianceAtBall * volume;
}

TEST_F(PostfxVolumeCausticsTest, EachRayScattersSigmaSTimesItsLengthTimesItsFlux) {
  const VolumeCausticScene scene = clearBallInThinWater();
  const double expected = expectedIntensity(scene, 1.0);
  for (postfx::VolumeCausticsMethod method :
       {postfx::VolumeCausticsMethod::Beams, postfx::VolumeCausticsMethod::Lines}) {
    postfx::ObjectCausticsSettings settings;
    settings.volume.method = method;
    const double measured = intensityTowardCamera(scene, volumeLight(scene, settings));
    const bool beams = method == postfx::VolumeCausticsMethod::Beams;
    std::printf("%s: %.6g of %.6g (%.4f)\n", beams ? "beams" : "lines", measured, expected,
                measured / expected);
    // Beams: the kernel integrates to 1 across every ray; lines: the raster's one fragment per
    // step, whose slant and ends round.
    EXPECT_NEAR(measured / expected, 1.0, beams ? 0.02 : 0.05);
  }
}

TEST_F(PostfxVolumeCausticsTest, APointLightsRaysScatterTheirFluxToo) {
  // The same ball under a point light 40 m above its centre: the rays nearly parallel, the
  // irradiance at the ball I / d^2 (the inverse square across the ball is symmetric to first
  // order).
  VolumeCausticScene scene = clearBallInThinWater();
  scene.waterLevel = 100.0;  // the light under water too (one above it would be skipped)
  scene.pointLightDistance = 40.0;
  scene.pointLightIntensity = glm::vec3(1600.0f);
  const double expected = expectedIntensity(scene, 1600.0 / (40.0 * 40.0));
  postfx::ObjectCausticsSettings settings;
  const double measured = intensityTowardCamera(scene, volumeLight(scene, settings));
  std::printf("point light: %.6g of %.6g (%.4f)\n", measured, expected, measured / expected);
  EXPECT_NEAR(measured / expected, 1.0, 0.04);
}

TEST_F(PostfxVolumeCausticsTest, AClearBallOfIorOneRefillsItsShadowInTheShafts) {
  // God rays through flat water, the ball in the host's shadow map: its shadow in the shafts
  // plus its volume caustic is the shafts without the ball (the light crossing the glass is
  // not extinguished by water: exp(sigma_t * 1 m) = 1.004 at most here).
  VolumeCausticScene scene = ocean::validation::glassSphereInWater(320, 180);
  scene.sphere.ior = 1.0;
  scene.scattering = glm::dvec3(0.002);
  scene.absorption = glm::dvec3(0.002);
  postfx::ObjectCausticsSettings settings;
  VolumeCausticOptions shafts;
  shafts.godRays = true;
  VolumeCausticOptions open = shafts;
  open.volume = false;
  open.shadowless = true;
  VolumeCausticOptions shadowed = shafts;
  shadowed.volume = false;
  const std::vector<glm::dvec3> filled = render(scene, settings, shafts);
  const std::vector<glm::dvec3> unshadowed = render(scene, settings, open);
  const std::vector<glm::dvec3> shadow = render(scene, settings, shadowed);
  double totals[3] = {0.0, 0.0, 0.0};
  for (size_t i = 0; i < filled.size(); ++i)
    totals[0] += filled[i].g, totals[1] += unshadowed[i].g, totals[2] += shadow[i].g;
  std::printf("frame sums: filled %.5g, open %.5g, shadowed %.5g\n", totals[0], totals[1],
              totals[2]);
  double sumFilled = 0.0, sumOpen = 0.0, sumShadow = 0.0, err = 0.0, ref = 0.0;
  int pixels = 0;
  // This host draws the wall alone: pixels whose view ray crosses the ball see through it, and
  // their shafts inside the glass (shadowed, and no water to scatter in) are nobody's. Left out.
  const double focal = 1.0 / std::tan(30.0 * kPi / 180.0);
  const double aspect = double(scene.width) / scene.height;
  auto seesBall = [&](size_t i) {
    const int x = int(i % size_t(scene.width)), y = int(i / size_t(scene.width));
    const glm::dvec3 d =
        glm::normalize(glm::dvec3(((x + 0.5) / scene.width * 2.0 - 1.0) * aspect / focal,
                                  ((y + 0.5) / scene.height * 2.0 - 1.0) / focal, -1.0));
    const double b = glm::dot(d, scene.sphere.centre);
    return b * b - glm::dot(scene.sphere.centre, scene.sphere.centre) +
               scene.sphere.radius * scene.sphere.radius >
           0.0;
  };
  for (size_t i = 0; i < filled.size(); ++i) {
    // The ball's shadow: where it takes at least a tenth of the shafts away.
    if (!(unshadowed[i].g - shadow[i].g > 0.1 * unshadowed[i].g) || seesBall(i)) continue;
    ++pixels;
    sumFilled += filled[i].g;
    sumOpen += unshadowed[i].g;
    sumShadow += shadow[i].g;
    err += (filled[i].g - unshadowed[i].g) * (filled[i].g - unshadowed[i].g);
    ref += unshadowed[i].g * unshadowed[i].g;
  }
  std::printf("shadow %d pixels: shadowed %.4f, filled %.4f of the open shafts, rel RMSE %.4f\n",
              pixels, sumShadow / sumOpen, sumFilled / sumOpen, std::sqrt(err / ref));
  ASSERT_GT(pixels, 500);
  EXPECT_LT(sumShadow / sumOpen, 0.9);  // the shadow is there without the volume
  EXPECT_NEAR(sumFilled / sumOpen, 1.0, 0.03);
  EXPECT_LT(std::sqrt(err / ref), 0.05);
}

TEST_F(PostfxVolumeCausticsTest, IorOneFocusesNothing) {
  // A focusing ball's cone is brightest at its focus; with IOR 1 the column is as bright
  // everywhere as one ray deep: its peak stays within 30 % of its median over the column.
  VolumeCausticScene scene = clearBallInThinWater();
  scene.towardSun = ocean::validation::glassSphereInWater(320, 180).towardSun;
  postfx::ObjectCausticsSettings settings;
  auto peakOverMedian = [&](const VolumeCausticScene& s) {
    const std::vector<glm::dvec3> light = volumeLight(s, settings);
    std::vector<double> lit;
    double peak = 0.0;
    for (const glm::dvec3& p : light)
      if (p.g > 0.0) lit.push_back(p.g), peak = std::max(peak, p.g);
    std::nth_element(lit.begin(), lit.begin() + std::ptrdiff_t(lit.size() / 2), lit.end());
    return lit.empty() ? 0.0 : peak / lit[lit.size() / 2];
  };
  const double clear = peakOverMedian(scene);
  VolumeCausticScene glass = scene;
  glass.sphere.ior = 1.5 / glass.waterIor;
  const double focusing = peakOverMedian(glass);
  std::printf("peak / median: IOR 1 %.3f, glass %.3f\n", clear, focusing);
  EXPECT_LT(clear, 1.3 * 2.2);  // a column's edge-on thickness: 2 R against its rim
  EXPECT_GT(focusing, 3.0 * clear);
}

TEST_F(PostfxVolumeCausticsTest, NothingInFrontOfAnOccluder) {
  // The wall 1.5 m from the camera, the ball 5 m behind it and its cone below it (no ray it
  // sends reaches the wall's side of the water): nothing shows.
  VolumeCausticScene scene = ocean::validation::glassSphereInWater(256, 144);
  scene.wallDistance = 1.5;
  const std::vector<glm::dvec3> light = volumeLight(scene, {});
  double most = 0.0;
  size_t at = 0;
  for (size_t i = 0; i < light.size(); ++i)
    if (light[i].g > most) most = light[i].g, at = i;
  EXPECT_EQ(most, 0.0) << "pixel " << at % 256 << ", " << at / 256;
  // The same ball with the wall behind it does show its cone.
  scene.wallDistance = 8.0;
  double lit = 0.0;
  for (const glm::dvec3& p : volumeLight(scene, {})) lit = std::max(lit, p.g);
  EXPECT_GT(lit, 0.0);
}

TEST_F(PostfxVolumeCausticsTest, OffChangesNothingBitForBit) {
  // A context with the feature and volume.enabled false, one without the feature: the same
  // object caustics, bit for bit.
  const VolumeCausticScene scene = ocean::validation::glassSphereInWater(256, 144);
  postfx::ObjectCausticsSettings disabled;
  disabled.volume.enabled = false;
  VolumeCausticOptions withFeature;
  const std::vector<glm::dvec3> a = render(scene, disabled, withFeature);
  VolumeCausticOptions without;
  without.volume = false;
  const std::vector<glm::dvec3> b = render(scene, disabled, without);
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i], b[i]) << "pixel " << i;
    if (a[i] != b[i]) break;
  }
  // The same context with the volume on does add light: the comparison could fail.
  const std::vector<glm::dvec3> on = render(scene, {}, withFeature);
  double added = 0.0;
  for (size_t i = 0; i < on.size(); ++i) added += on[i].g - a[i].g;
  EXPECT_GT(added, 0.0);
}

TEST_F(PostfxVolumeCausticsTest, BadInputIsRefusedByName) {
  const VolumeCausticScene scene = ocean::validation::glassSphereInWater(64, 36);
  VolumeCausticRun run;
  std::string error;
  postfx::ObjectCausticsSettings bad;
  bad.volume.method = static_cast<postfx::VolumeCausticsMethod>(7);
  EXPECT_FALSE(ocean::validation::runVolumeCaustic(scene, bad, {}, run, error));
  EXPECT_NE(error.find("volume.method"), std::string::npos) << error;
  // A fog after dispatch would attenuate the in-scattered light twice.
  VolumeCausticOptions host;
  host.hostExtinction = true;
  error.clear();
  EXPECT_FALSE(ocean::validation::runVolumeCaustic(scene, {}, host, run, error));
  EXPECT_NE(error.find("viewExtinction Host"), std::string::npos) << error;
  // The god rays' phase, read by the volume even without Feature::GodRays.
  VolumeCausticScene nan = scene;
  nan.phase = std::nan("");
  error.clear();
  EXPECT_FALSE(ocean::validation::runVolumeCaustic(nan, {}, {}, run, error));
  EXPECT_NE(error.find("godRays.intensity"), std::string::npos) << error;
  // Off, the same frames are accepted: the refusals are the volume's.
  VolumeCausticOptions off = host;
  off.volume = false;
  EXPECT_TRUE(ocean::validation::runVolumeCaustic(scene, {}, off, run, error)) << error;
}

TEST_F(PostfxVolumeCausticsTest, ItsMemoryCountsAgainstTheBudget) {
  // At 640x360 and the default grid and map the object caustics need 17.3 MiB; the volume adds
  // 48 bytes per ray (3 MiB) and a float texture of the view (3.5 MiB). A 20 MiB budget holds
  // the first (18 MiB) and refuses the second (24 MiB) up front.
  const VolumeCausticScene scene = ocean::validation::glassSphereInWater(640, 360);
  VolumeCausticOptions tight;
  tight.memoryBudgetMiB = 20;
  VolumeCausticRun run;
  std::string error;
  EXPECT_FALSE(ocean::validation::runVolumeCaustic(scene, {}, tight, run, error));
  EXPECT_NE(error.find("needs 24 MiB"), std::string::npos) << error;
  tight.volume = false;
  error.clear();
  EXPECT_TRUE(ocean::validation::runVolumeCaustic(scene, {}, tight, run, error)) << error;
}

TEST_F(PostfxVolumeCausticsTest, ExtremeViewsStayFiniteAndBounded) {
  // The camera inside the cone at its focus, looking along it and across it; a sun at grazing
  // incidence; a ball touching the surface; no scattering at all.
  VolumeCausticScene base = ocean::validation::glassSphereInWater(128, 72);
  const double total = expectedIntensity(base, 1.0) / base.scattering.g * 1e3;
  std::vector<VolumeCausticScene> cases;
  VolumeCausticScene atFocus = base;
  atFocus.sphere.centre = {0.0, 2.25 * 1.0, 0.0};  // the paraxial focus at the camera
  atFocus.towardSun = {0.0, 1.0, 0.0};
  cases.push_back(atFocus);
  VolumeCausticScene grazing = base;
  grazing.towardSun = glm::normalize(glm::dvec3(1.0, 0.02, 0.0));
  cases.push_back(grazing);
  VolumeCausticScene surface = base;
  surface.waterLevel = base.sphere.centre.y + 0.1;
  cases.push_back(surface);
  VolumeCausticScene dense = base;
  dense.scattering = glm::dvec3(50.0);
  dense.absorption = glm::dvec3(50.0);
  cases.push_back(dense);
  for (const VolumeCausticScene& scene : cases) {
    for (postfx::VolumeCausticsMethod method :
         {postfx::VolumeCausticsMethod::Beams, postfx::VolumeCausticsMethod::Lines}) {
      postfx::ObjectCausticsSettings settings;
      settings.volume.method = method;
      const std::vector<glm::dvec3> light = render(scene, settings, {});
      for (const glm::dvec3& p : light) {
        ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
        ASSERT_GE(std::min({p.r, p.g, p.b}), 0.0);
        ASSERT_LT(std::max({p.r, p.g, p.b}), total);
      }
    }
  }
}

TEST_F(PostfxVolumeCausticsTest, TheConeAgreesWithTheTracedBeamsAt640x360) {
  const VolumeCausticScene scene = ocean::validation::glassSphereInWater(640, 360);
  const std::vector<glm::dvec3> reference =
      ocean::validation::volumeCausticReference(scene, 800, 0, false);
  for (postfx::VolumeCausticsMethod method :
       {postfx::VolumeCausticsMethod::Beams, postfx::VolumeCausticsMethod::Lines}) {
    postfx::ObjectCausticsSettings settings;
    settings.volume.method = method;
    const ocean::validation::ConeError e =
        ocean::validation::coneError(volumeLight(scene, settings), reference);
    const bool beams = method == postfx::VolumeCausticsMethod::Beams;
    std::printf("%s: relative RMSE %.4f, flux %.4f, correlation %.4f over %d pixels\n",
                beams ? "beams" : "lines", e.relativeRmse, e.fluxRatio, e.correlation, e.pixels);
    EXPECT_GT(e.pixels, 2000);
    EXPECT_LE(e.relativeRmse, 0.3);
    EXPECT_NEAR(e.fluxRatio, 1.0, 0.1);
  }
}

}  // namespace
