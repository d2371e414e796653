// Object caustics against exact CPU ray tracing (the caustics-mapping glass sphere, the metal
// ring's cardioid): focus position, total flux, caustic curve; and the error/time table over map
// size, grid size and hit iterations.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "gl_fixture.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;

class PostfxObjectCausticsAccuracyTest : public testsupport::GlTest {};

struct SphereRun {
  double focusErrorVsReference = 0.0;  // fraction of the radius
  double focusErrorVsAxis = 0.0;       // fraction of the radius
  glm::dvec3 fluxError{0.0};           // relative, per channel
  double ms = 0.0;
};

// The report's glass sphere over a plane (ocean::reference::glassSphereOverPlane: R = 1, IOR 1.5,
// tinted glass, 0.4 m above the plane y = 0, sun 25 degrees from the zenith): the axial caustic
// lands where the line through the centre along the light meets the plane.
SphereRun runSphere(const postfx::ObjectCausticsSettings& settings, int referenceRays, bool print) {
  const ocean::reference::SphereOverPlane scene = ocean::reference::glassSphereOverPlane();
  const glm::dvec3 sun = scene.towardSun;
  ObjectHost host(sun);
  const GlMesh mesh = makeSphereMesh(scene.sphere.radius, 160, 80);
  const SphereCaster& sphere = scene.sphere;
  postfx::CasterMaterial glass;
  glass.ior = float(sphere.ior);
  glass.absorption = glm::vec3(sphere.absorption);
  const postfx::CasterMesh caster = mesh.caster(translation(sphere.centre), glass);
  auto fx = makeObjectContext();
  const postfx::FrameDesc frame = host.frame(&caster, 1, settings);
  for (int i = 0; i < 6; ++i)
    EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  glFinish();
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  SphereRun run;
  run.ms = postfx::stats(*fx).pass(postfx::Pass::ObjectCaustics).medianMs;
  const postfx::ObjectCausticMap map = postfx::objectCausticMap(*fx);
  const std::vector<glm::dvec3> gpu = readObjectMap(map);
  EXPECT_TRUE(allFinite(gpu));

  const CausticReference ref = traceSphereReference(sphere, sun, 0.0, map, referenceRays);
  const std::vector<glm::dvec3> blurred =
      gaussianBlur(ref.irradiance, map.size, settings.splatRadius);
  const glm::dvec3 gpuFocus = texelOnPlane(map, focusTexel(gpu, map.size), 0.0);
  const glm::dvec3 refFocus = texelOnPlane(map, focusTexel(blurred, map.size), 0.0);
  const glm::dvec3 axisFocus = sphere.centre - sun * (sphere.centre.y / sun.y);
  run.focusErrorVsReference = glm::length(gpuFocus - refFocus) / sphere.radius;
  run.focusErrorVsAxis = glm::length(gpuFocus - axisFocus) / sphere.radius;
  const glm::dvec3 gpuFlux = mapFlux(gpu, map);
  run.fluxError = gpuFlux / ref.fluxInMap - 1.0;
  if (print) {
    const glm::dvec3 total = ref.fluxInMap + ref.fluxOutside;
    std::printf(
        "sphere: intercepted area %.5f m^2 (pi R^2 = %.5f); reference flux in map (%.5f %.5f "
        "%.5f), outside %.5f%%; GPU flux (%.5f %.5f %.5f)\n",
        ref.interceptedArea, kPi, ref.fluxInMap.r, ref.fluxInMap.g, ref.fluxInMap.b,
        100.0 * ref.fluxOutside.g / total.g, gpuFlux.r, gpuFlux.g, gpuFlux.b);
    std::printf("sphere: mean transmittance after Fresnel and absorption (%.4f %.4f %.4f)\n",
                total.r / ref.interceptedArea, total.g / ref.interceptedArea,
                total.b / ref.interceptedArea);
    std::printf(
        "sphere: focus GPU (%.4f, %.4f) reference (%.4f, %.4f) axis (%.4f, %.4f) m; error vs "
        "reference %.3f%% of R, vs axis %.3f%% of R\n",
        gpuFocus.x, gpuFocus.z, refFocus.x, refFocus.z, axisFocus.x, axisFocus.z,
        100.0 * run.focusErrorVsReference, 100.0 * run.focusErrorVsAxis);
    std::printf("sphere: flux error (%.3f%% %.3f%% %.3f%%), pass %.3f ms\n",
                100.0 * run.fluxError.r, 100.0 * run.fluxError.g, 100.0 * run.fluxError.b, run.ms);
  }
  return run;
}

TEST_F(PostfxObjectCausticsAccuracyTest, GlassSphereMatchesExactRayTracing) {
  postfx::ObjectCausticsSettings s;
  s.mapSize = 512;
  s.gridSize = 512;
  s.footprintScale = 3.0f;  // defaults otherwise: 1 receiver iteration (caustics mapping's), 5 exit
  const SphereRun run = runSphere(s, 2400, true);
  // Issue #7: focus within 2 % of the radius, flux within 5 %.
  EXPECT_LT(run.focusErrorVsReference, 0.02);
  EXPECT_LT(run.focusErrorVsAxis, 0.02);
  for (int c = 0; c < 3; ++c) EXPECT_LT(std::abs(run.fluxError[c]), 0.05) << "channel " << c;
}

TEST_F(PostfxObjectCausticsAccuracyTest, ErrorAgainstTimeTable) {
  struct Row {
    int map, grid, iterations, exit;
  };
  const Row rows[] = {{256, 128, 1, 5}, {256, 256, 1, 5}, {512, 256, 1, 5},  {512, 512, 1, 5},
                      {512, 512, 3, 5}, {512, 512, 5, 5}, {1024, 512, 1, 5}, {512, 512, 1, 1},
                      {512, 512, 1, 2}, {512, 512, 1, 3}};
  std::printf(
      "| map | grid | receiver iterations | exit iterations | focus error (%% R) | flux error G "
      "(%%) | GPU ms |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  double fluxErrorByExit[9] = {};
  for (const Row& row : rows) {
    postfx::ObjectCausticsSettings s;
    s.mapSize = row.map;
    s.gridSize = row.grid;
    s.iterations = row.iterations;
    s.exitIterations = row.exit;
    s.footprintScale = 3.0f;
    s.splatRadius = row.map >= 1024 ? 2.0f : 1.0f;
    const SphereRun run = runSphere(s, 1200, false);
    std::printf("| %d | %d | %d | %d | %.3f | %.3f | %.3f |\n", row.map, row.grid, row.iterations,
                row.exit, 100.0 * run.focusErrorVsReference, 100.0 * run.fluxError.g, run.ms);
    // The axial focus is found at every setting (the 2 % of R). The flux needs the exit
    // search converged: with 1-2 exit iterations rim rays leave through a misplaced back normal
    // and are lost to total internal reflection.
    EXPECT_LT(run.focusErrorVsReference, 0.02);
    if (row.exit >= 3) {
      EXPECT_LT(std::abs(run.fluxError.g), 0.05);
    }
    if (row.map == 512 && row.grid == 512 && row.iterations == 1)
      fluxErrorByExit[row.exit] = std::abs(run.fluxError.g);
  }
  EXPECT_LE(fluxErrorByExit[5], fluxErrorByExit[3]);
  EXPECT_LE(fluxErrorByExit[3], fluxErrorByExit[2]);
  EXPECT_LE(fluxErrorByExit[2], fluxErrorByExit[1]);
}

TEST_F(PostfxObjectCausticsAccuracyTest, IorOneRefillsTheShadowWithoutFocus) {
  // IOR 1: no bending and no Fresnel loss, so every ray lands where the shadow is, with the
  // sun's full irradiance: the caustic is exactly 1 inside the projected disc and has no peak.
  const glm::dvec3 sun = sunAt(20.0, 0.0);
  ObjectHost host(sun);
  const GlMesh mesh = makeSphereMesh(1.0, 160, 80);
  postfx::CasterMaterial air;
  air.ior = 1.0f;
  const glm::dvec3 centre(0.0, 1.5, 0.0);
  const postfx::CasterMesh caster = mesh.caster(translation(centre), air);
  auto fx = makeObjectContext();
  postfx::ObjectCausticsSettings s;
  s.gridSize = 256;
  s.mapSize = 512;
  ASSERT_EQ(postfx::dispatch(*fx, host.frame(&caster, 1, s)), postfx::Result::Ok)
      << postfx::lastError(fx.get());
  const postfx::ObjectCausticMap map = postfx::objectCausticMap(*fx);
  const std::vector<glm::dvec3> gpu = readObjectMap(map);
  const double u2 = glm::dot(map.axisU, map.axisU);
  const glm::dvec2 c(glm::dot(centre - map.origin, map.axisU) / u2 * map.size,
                     glm::dot(centre - map.origin, map.axisV) / u2 * map.size);
  const double radiusTexels = 1.0 / glm::length(map.axisU) * map.size;
  double lo = 1e30, hi = 0.0, peak = 0.0;
  for (int y = 0; y < map.size; ++y)
    for (int x = 0; x < map.size; ++x) {
      const double v = gpu[y * map.size + x].g;
      peak = std::max(peak, v);
      if (glm::length(glm::dvec2(x + 0.5, y + 0.5) - c) > 0.9 * radiusTexels) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  std::printf("IOR 1: caustic inside the shadow in [%.4f, %.4f], peak anywhere %.4f\n", lo, hi,
              peak);
  EXPECT_GT(lo, 0.97);
  EXPECT_LT(hi, 1.03);
  EXPECT_LT(peak, 1.05);
}

TEST_F(PostfxObjectCausticsAccuracyTest, ReflectiveRingGivesTheCardioid) {
  const glm::dvec3 sun = sunAt(60.0, 20.0);  // 30 degrees above the horizon
  ObjectHost host(sun);
  RingCaster ring;
  ring.inner = 1.0;
  ring.outer = 1.05;
  ring.height = 0.5;
  ring.f0 = glm::dvec3(0.9, 0.8, 0.6);  // gold-ish: Schlick per channel
  const GlMesh mesh = makeRingMesh(ring.inner, ring.outer, ring.height, 512);
  postfx::CasterMaterial metal;
  metal.type = postfx::CasterMaterialType::Reflective;
  metal.reflectance = glm::vec3(ring.f0);
  const postfx::CasterMesh caster = mesh.caster(glm::dmat4(1.0), metal);
  auto fx = makeObjectContext();
  postfx::ObjectCausticsSettings s;
  s.mapSize = 512;
  s.gridSize = 512;
  s.footprintScale = 2.0f;
  ASSERT_EQ(postfx::dispatch(*fx, host.frame(&caster, 1, s)), postfx::Result::Ok)
      << postfx::lastError(fx.get());
  const postfx::ObjectCausticMap map = postfx::objectCausticMap(*fx);
  const std::vector<glm::dvec3> gpu = readObjectMap(map);
  ASSERT_TRUE(allFinite(gpu));
  const CausticReference ref = traceRingReference(ring, sun, 0.0, map, 2400);
  const std::vector<glm::dvec3> blurred = gaussianBlur(ref.irradiance, map.size, s.splatRadius);

  const glm::dvec3 gpuFlux = mapFlux(gpu, map);
  const glm::dvec3 fluxError = gpuFlux / ref.fluxInMap - 1.0;
  // The caustic curve: texels at >= 25 % of each map's maximum, compared by their mean
  // distance to the other map's set (both ways).
  auto bright = [&map](const std::vector<glm::dvec3>& m) {
    double peak = 0.0;
    for (const glm::dvec3& v : m) peak = std::max(peak, v.g);
    std::vector<glm::dvec3> points;
    for (int y = 0; y < map.size; ++y)
      for (int x = 0; x < map.size; ++x)
        if (m[y * map.size + x].g >= 0.25 * peak)
          points.push_back(texelOnPlane(map, glm::dvec2(x + 0.5, y + 0.5), 0.0));
    return points;
  };
  const std::vector<glm::dvec3> a = bright(gpu), b = bright(blurred);
  auto meanNearest = [](const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to) {
    double sum = 0.0;
    for (const glm::dvec3& p : from) {
      double best = 1e30;
      for (const glm::dvec3& q : to) best = std::min(best, glm::dot(p - q, p - q));
      sum += std::sqrt(best);
    }
    return sum / double(from.size());
  };
  const double curveError = std::max(meanNearest(a, b), meanNearest(b, a)) / ring.inner;
  const glm::dvec3 gpuPeak = texelOnPlane(map, focusTexel(gpu, map.size), 0.0);
  const glm::dvec3 refPeak = texelOnPlane(map, focusTexel(blurred, map.size), 0.0);
  const double cuspError = glm::length(gpuPeak - refPeak) / ring.inner;
  std::printf(
      "ring: bright texels GPU %zu reference %zu; caustic-curve distance %.3f%% of R; cusp GPU "
      "(%.4f, %.4f) reference (%.4f, %.4f), error %.3f%% of R\n",
      a.size(), b.size(), 100.0 * curveError, gpuPeak.x, gpuPeak.z, refPeak.x, refPeak.z,
      100.0 * cuspError);
  std::printf(
      "ring: flux GPU (%.5f %.5f %.5f) reference (%.5f %.5f %.5f), error (%.3f%% %.3f%% "
      "%.3f%%)\n",
      gpuFlux.r, gpuFlux.g, gpuFlux.b, ref.fluxInMap.r, ref.fluxInMap.g, ref.fluxInMap.b,
      100.0 * fluxError.r, 100.0 * fluxError.g, 100.0 * fluxError.b);
  EXPECT_LT(curveError, 0.03);
  EXPECT_LT(cuspError, 0.03);
  for (int c = 0; c < 3; ++c) EXPECT_LT(std::abs(fluxError[c]), 0.05) << "channel " << c;
}

TEST_F(PostfxObjectCausticsAccuracyTest, UnderWaterTheLightIsTheRefractedSun) {
  // Casters below the water level: the light reaching them travels along the sun refracted by
  // the (mean) water surface, and the glass bends it by IOR_glass / IOR_water only.
  const glm::dvec3 sun = sunAt(50.0, -30.0);
  const double waterIor = 1.333;
  const glm::dvec3 travel = glm::refract(-sun, glm::dvec3(0.0, 1.0, 0.0), 1.0 / waterIor);
  ObjectHost host(-travel);  // the host's receiver map looks along the refracted light
  const GlMesh mesh = makeSphereMesh(1.0, 160, 80);
  SphereCaster sphere;
  sphere.centre = {-0.2, 1.4, 0.3};
  sphere.ior = 1.5 / waterIor;
  postfx::CasterMaterial glassMaterial;
  glassMaterial.ior = 1.5f;
  const postfx::CasterMesh caster = mesh.caster(translation(sphere.centre), glassMaterial);
  auto fx = makeObjectContext();
  // A weak lens (relative IOR 1.125) seen at 35 degrees: caustics mapping's single receiver
  // iteration leaves a few per cent of R; three converge.
  for (int iterations : {1, 3}) {
    postfx::ObjectCausticsSettings s;
    s.mapSize = 512;
    s.gridSize = 512;
    s.iterations = iterations;
    s.footprintScale = 3.0f;
    postfx::FrameDesc frame = host.frame(&caster, 1, s);
    frame.sun.direction = sun;
    frame.water.level = 10.0;
    frame.water.ior = float(waterIor);
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    const postfx::ObjectCausticMap map = postfx::objectCausticMap(*fx);
    const double directionError = glm::length(map.direction - glm::normalize(travel));
    const std::vector<glm::dvec3> gpu = readObjectMap(map);
    const CausticReference ref = traceSphereReference(sphere, -travel, 0.0, map, 2000);
    const std::vector<glm::dvec3> blurred = gaussianBlur(ref.irradiance, map.size, s.splatRadius);
    const double focusError = glm::length(texelOnPlane(map, focusTexel(gpu, map.size), 0.0) -
                                          texelOnPlane(map, focusTexel(blurred, map.size), 0.0));
    const glm::dvec3 fluxError = mapFlux(gpu, map) / ref.fluxInMap - 1.0;
    double peakGpu = 0.0, peakRef = 0.0;
    for (size_t i = 0; i < gpu.size(); ++i) {
      peakGpu = std::max(peakGpu, gpu[i].g);
      peakRef = std::max(peakRef, blurred[i].g);
    }
    std::printf(
        "under water, %d receiver iteration(s): light direction error %.2e; focus error %.3f%% "
        "of R; flux error %.3f%%; peak GPU %.2f reference %.2f (relative IOR %.4f)\n",
        iterations, directionError, 100.0 * focusError / sphere.radius, 100.0 * fluxError.g,
        peakGpu, peakRef, sphere.ior);
    EXPECT_LT(directionError, 1e-6);
    EXPECT_LT(focusError / sphere.radius, iterations >= 3 ? 0.02 : 0.05);
    EXPECT_LT(std::abs(fluxError.g), 0.05);
  }
}

}  // namespace
