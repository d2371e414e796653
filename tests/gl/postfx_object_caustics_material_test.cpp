// The glTF-style glass fields of postfx::CasterMaterial change the caustic as the
// glTF extensions mean: the transmission weight scales the flux, the tint colours it, thicker
// absorbing glass darkens it per Beer-Lambert, thin-walled glass does not focus, roughness
// widens the caustic by the stated cone, dispersion separates the channels' foci; each against
// the closed form or the CPU ray tracer given the same material. And every new field is
// validated.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "gl_fixture.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

class PostfxObjectCausticsMaterialTest : public testsupport::GlTest {};

glm::dmat4 scaled(const glm::dvec3& centre, const glm::dvec3& scale) {
  glm::dmat4 m = translation(centre);
  for (int a = 0; a < 3; ++a) m[a][a] = scale[a];
  return m;
}

struct MapResult {
  postfx::ObjectCausticMap map;
  std::vector<glm::dvec3> texels;
  glm::dvec3 flux{0.0};
};

MapResult runCasters(const ObjectHost& host, const postfx::CasterMesh* casters, int count,
                     const postfx::ObjectCausticsSettings& s,
                     postfx::Feature extra = postfx::Feature::None) {
  auto fx = makeObjectContext(extra);
  MapResult r;
  const Result result = postfx::dispatch(*fx, host.frame(casters, count, s));
  EXPECT_EQ(result, Result::Ok) << postfx::lastError(fx.get());
  r.map = postfx::objectCausticMap(*fx);
  r.texels = readObjectMap(r.map);
  EXPECT_TRUE(allFinite(r.texels));
  r.flux = mapFlux(r.texels, r.map);
  return r;
}

// Flux-weighted variance (m^2) of one channel of a map along its u axis, and along its v axis.
glm::dvec2 mapVariance(const std::vector<glm::dvec3>& texels, const postfx::ObjectCausticMap& map,
                       int channel) {
  const double side = glm::length(map.axisU) / map.size;
  double sum = 0.0;
  glm::dvec2 mean(0.0), square(0.0);
  for (int y = 0; y < map.size; ++y)
    for (int x = 0; x < map.size; ++x) {
      const double w = texels[y * map.size + x][channel];
      const glm::dvec2 p((x + 0.5) * side, (y + 0.5) * side);
      sum += w;
      mean += w * p;
      square += w * p * p;
    }
  mean /= sum;
  return square / sum - mean * mean;
}

// A 0.5 m glass cube 1 m above the plane, the sun at the zenith: every ray crosses two faces at
// normal incidence and the same 0.5 m of glass.
constexpr double kCubeHalf = 0.25;
const glm::dvec3 kCubeCentre(0.0, 1.0, 0.0);

postfx::ObjectCausticsSettings cubeSettings() {
  postfx::ObjectCausticsSettings s;
  s.mapSize = 256;
  s.gridSize = 256;
  return s;
}

TEST_F(PostfxObjectCausticsMaterialTest, TransmissionWeightScalesTheFlux) {
  const ObjectHost host(sunAt(0.0, 0.0));
  const GlMesh cube = makeCubeMesh(kCubeHalf);
  const float weights[] = {1.0f, 0.5f, 0.05f};
  double flux[3] = {};
  for (int i = 0; i < 3; ++i) {
    postfx::CasterMaterial glass;
    glass.transmission = weights[i];
    const postfx::CasterMesh caster = cube.caster(translation(kCubeCentre), glass);
    flux[i] = runCasters(host, &caster, 1, cubeSettings()).flux.g;
  }
  // Normal incidence at IOR 1.5: each face reflects 4 %, the cube lets (1 - 0.04)^2 through.
  const double expected = 0.96 * 0.96 * (2.0 * kCubeHalf) * (2.0 * kCubeHalf);
  std::printf(
      "transmission 1 / 0.5 / 0.05: flux %.5f %.5f %.5f m^2 (closed form %.5f at 1), "
      "ratios %.5f %.5f\n",
      flux[0], flux[1], flux[2], expected, flux[1] / flux[0], flux[2] / flux[0]);
  EXPECT_NEAR(flux[0] / expected, 1.0, 0.03);  // silhouette texels of the 256^2 ray grid
  EXPECT_NEAR(flux[1] / flux[0], 0.5, 1e-4);
  EXPECT_NEAR(flux[2] / flux[0], 0.05, 1e-5);
}

TEST_F(PostfxObjectCausticsMaterialTest, TintColoursTheTransmittedLight) {
  const ObjectHost host(sunAt(0.0, 0.0));
  const GlMesh cube = makeCubeMesh(kCubeHalf);
  postfx::CasterMaterial clear, red;
  red.tint = glm::vec3(1.0f, 0.2f, 0.05f);
  const postfx::CasterMesh a = cube.caster(translation(kCubeCentre), clear);
  const postfx::CasterMesh b = cube.caster(translation(kCubeCentre), red);
  const glm::dvec3 clearFlux = runCasters(host, &a, 1, cubeSettings()).flux;
  const glm::dvec3 redFlux = runCasters(host, &b, 1, cubeSettings()).flux;
  const glm::dvec3 ratio = redFlux / clearFlux;
  std::printf("red tint (1, 0.2, 0.05): flux ratio to clear glass (%.5f %.5f %.5f)\n", ratio.r,
              ratio.g, ratio.b);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(ratio[c], red.tint[c], 1e-4) << "channel " << c;
}

TEST_F(PostfxObjectCausticsMaterialTest, ThickerAbsorbingGlassIsDarkerPerBeerLambert) {
  const ObjectHost host(sunAt(0.0, 0.0));
  const GlMesh cube = makeCubeMesh(kCubeHalf);
  postfx::CasterMaterial clear, coloured;
  coloured.absorption = glm::vec3(0.1f, 0.6f, 2.0f);  // per metre
  // The same footprint, 0.5 m and 1 m of glass along the light.
  const postfx::CasterMesh clearThin = cube.caster(translation(kCubeCentre), clear);
  const postfx::CasterMesh thin = cube.caster(translation(kCubeCentre), coloured);
  const postfx::CasterMesh thick = cube.caster(scaled(kCubeCentre, {1.0, 2.0, 1.0}), coloured);
  const glm::dvec3 f0 = runCasters(host, &clearThin, 1, cubeSettings()).flux;
  const glm::dvec3 f1 = runCasters(host, &thin, 1, cubeSettings()).flux;
  const glm::dvec3 f2 = runCasters(host, &thick, 1, cubeSettings()).flux;
  for (int c = 0; c < 3; ++c) {
    const double d = 2.0 * kCubeHalf, a = coloured.absorption[c];
    std::printf("channel %d: 0.5 m / clear %.5f (exp(-a d) %.5f), 1 m / 0.5 m %.5f (%.5f)\n", c,
                f1[c] / f0[c], std::exp(-a * d), f2[c] / f1[c], std::exp(-a * d));
    EXPECT_NEAR(f1[c] / f0[c] / std::exp(-a * d), 1.0, 0.01) << "channel " << c;
    EXPECT_NEAR(f2[c] / f1[c] / std::exp(-a * d), 1.0, 0.01) << "channel " << c;
  }
}

// The report's glass sphere (R = 1 m, IOR 1.5, 0.4 m above the plane, sun 25 degrees from the
// zenith): the GPU against the CPU ray tracer given the same material.
struct SphereComparison {
  glm::dvec3 gpuFlux{0.0}, refFlux{0.0};
  glm::dvec2 gpuVariance{0.0}, refVariance{0.0};  // green, m^2
  double gpuPeak = 0.0;
  glm::dvec2 focus{0.0};            // the trace's brightest spot (texels)
  std::vector<glm::dvec3> blurred;  // the trace blurred by the GPU's splat
  MapResult gpu;
  CausticReference ref;
};

SphereComparison compareSphere(const SphereCaster& sphere, const glm::dvec3& sun,
                               postfx::Feature extra = postfx::Feature::None) {
  const ObjectHost host(sun);
  const GlMesh mesh = makeSphereMesh(sphere.radius, 160, 80);
  postfx::CasterMaterial m;
  m.ior = float(sphere.ior);
  m.absorption = glm::vec3(sphere.absorption);
  m.transmission = float(sphere.transmission);
  m.tint = glm::vec3(sphere.tint);
  m.thinWalled = sphere.thinWalled;
  m.roughness = float(sphere.roughness);
  m.dispersion = float(sphere.dispersion);
  const postfx::CasterMesh caster = mesh.caster(translation(sphere.centre), m);
  postfx::ObjectCausticsSettings s;
  s.mapSize = 512;
  s.gridSize = 512;
  s.footprintScale = 3.0f;
  // A converged receiver search: with caustics mapping's single iteration the strongly bent rim
  // rays land short of where the trace puts them (the flux and the focus agree either way).
  s.iterations = 5;
  SphereComparison out;
  out.gpu = runCasters(host, &caster, 1, s, extra);
  out.ref = traceSphereReference(sphere, sun, 0.0, out.gpu.map, 1600);
  const std::vector<glm::dvec3> blurred = gaussianBlur(out.ref.irradiance, s.mapSize, 1.0);
  out.gpuFlux = out.gpu.flux;
  out.refFlux = out.ref.fluxInMap;
  out.gpuVariance = mapVariance(out.gpu.texels, out.gpu.map, 1);
  out.refVariance = mapVariance(blurred, out.gpu.map, 1);
  for (const glm::dvec3& v : out.gpu.texels) out.gpuPeak = std::max(out.gpuPeak, v.g);
  out.focus = focusTexel(blurred, s.mapSize);
  out.blurred = blurred;
  return out;
}

// Flux (m^2, sun irradiance 1) of one channel within `radius` metres of a map texel position.
double fluxWithin(const std::vector<glm::dvec3>& texels, const postfx::ObjectCausticMap& map,
                  const glm::dvec2& centreTexel, double radius, int channel) {
  const double side = glm::length(map.axisU) / map.size;
  double sum = 0.0;
  for (int y = 0; y < map.size; ++y)
    for (int x = 0; x < map.size; ++x)
      if (glm::length(glm::dvec2(x + 0.5, y + 0.5) - centreTexel) * side <= radius)
        sum += texels[y * map.size + x][channel] * side * side;
  return sum;
}

SphereCaster reportSphere() {
  SphereCaster s = ocean::reference::glassSphereOverPlane().sphere;
  s.absorption = glm::dvec3(0.0);
  return s;
}

const glm::dvec3 kReportSun = ocean::reference::glassSphereOverPlane().towardSun;

TEST_F(PostfxObjectCausticsMaterialTest, ThinWalledGlassTransmitsWithoutFocusing) {
  SphereCaster solid = reportSphere();
  SphereCaster thin = solid;
  thin.thinWalled = true;
  thin.absorption = glm::dvec3(0.5);  // no volume: must not darken a thin wall
  const SphereComparison a = compareSphere(solid, kReportSun);
  const SphereComparison b = compareSphere(thin, kReportSun);
  std::printf("solid sphere: peak %.3f, flux %.5f (reference %.5f)\n", a.gpuPeak, a.gpuFlux.g,
              a.refFlux.g);
  std::printf(
      "thin-walled sphere: peak %.3f, flux %.5f (reference %.5f), variance (%.5f %.5f) "
      "m^2 (reference %.5f %.5f)\n",
      b.gpuPeak, b.gpuFlux.g, b.refFlux.g, b.gpuVariance.x, b.gpuVariance.y, b.refVariance.x,
      b.refVariance.y);
  EXPECT_GT(a.gpuPeak, 5.0);   // the solid sphere focuses
  EXPECT_LT(b.gpuPeak, 1.02);  // the thin wall refills its shadow at most with the sun's light
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(b.gpuFlux[c] / b.refFlux[c], 1.0, 0.03);
  // The projected disc of radius R: variance R^2 / 4 across the light, wider along the slant.
  EXPECT_NEAR(b.gpuVariance.x / b.refVariance.x, 1.0, 0.03);
  EXPECT_NEAR(b.gpuVariance.y / b.refVariance.y, 1.0, 0.03);
}

TEST_F(PostfxObjectCausticsMaterialTest, RoughnessWidensTheCausticByItsCone) {
  // IOR 1: the rays go straight through a 0.2 m cube and leave its bottom face 1.9 m above the
  // plane. Roughness 0.2 = alpha 0.04 rad: each ray's light spreads by 0.04 * 1.9 m, which adds
  // (0.076 m)^2 to the caustic's variance along each axis and leaves its flux alone.
  const ObjectHost host(sunAt(0.0, 0.0));
  const GlMesh cube = makeCubeMesh(0.1);
  postfx::CasterMaterial smooth, rough;
  smooth.ior = rough.ior = 1.0f;
  rough.roughness = 0.2f;
  const glm::dvec3 centre(0.0, 2.0, 0.0);
  const postfx::CasterMesh a = cube.caster(translation(centre), smooth);
  const postfx::CasterMesh b = cube.caster(translation(centre), rough);
  postfx::ObjectCausticsSettings s;
  s.mapSize = 256;  // 6.6 mm texels: the spread is 11.5 texels, under kMaxRoughSplatSigma
  s.gridSize = 128;
  s.footprintScale = 8.0f;
  const MapResult ra = runCasters(host, &a, 1, s);
  const MapResult rb = runCasters(host, &b, 1, s);
  const glm::dvec2 va = mapVariance(ra.texels, ra.map, 1), vb = mapVariance(rb.texels, rb.map, 1);
  const double added = std::pow(0.04 * 1.9, 2.0);
  std::printf(
      "roughness 0.2: variance (%.6f %.6f) -> (%.6f %.6f) m^2, added (%.6f %.6f), "
      "expected %.6f; flux %.5f -> %.5f\n",
      va.x, va.y, vb.x, vb.y, vb.x - va.x, vb.y - va.y, added, ra.flux.g, rb.flux.g);
  EXPECT_NEAR((vb.x - va.x) / added, 1.0, 0.05);
  EXPECT_NEAR((vb.y - va.y) / added, 1.0, 0.05);
  EXPECT_NEAR(rb.flux.g / ra.flux.g, 1.0, 1e-3);
  double peakA = 0.0, peakB = 0.0;
  for (const glm::dvec3& v : ra.texels) peakA = std::max(peakA, v.g);
  for (const glm::dvec3& v : rb.texels) peakB = std::max(peakB, v.g);
  EXPECT_LT(peakB, 0.8 * peakA);  // wider and dimmer, never brighter
}

TEST_F(PostfxObjectCausticsMaterialTest, TintedRoughPartlyTransmissiveSphereMatchesTheTrace) {
  // Absorbing glass, 60 % transmission, a red-orange tint and roughness 0.3 (a 0.09 rad cone,
  // about 0.13 m on the plane, 11 map texels): the flux per channel and how it gathers around
  // the focus, GPU against the trace.
  SphereCaster smooth = ocean::reference::glassSphereOverPlane().sphere;
  smooth.transmission = 0.6;
  smooth.tint = glm::dvec3(0.9, 0.5, 0.2);
  SphereCaster rough = smooth;
  rough.roughness = 0.3;
  const SphereComparison a = compareSphere(smooth, kReportSun);
  const SphereComparison r = compareSphere(rough, kReportSun);
  const glm::dvec3 fluxRatio = r.gpuFlux / r.refFlux;
  std::printf("tinted rough sphere: flux GPU / trace (%.4f %.4f %.4f)\n", fluxRatio.r, fluxRatio.g,
              fluxRatio.b);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fluxRatio[c], 1.0, 0.05) << "channel " << c;
  for (double radius : {0.05, 0.1, 0.25, 0.5}) {
    const double gpu = fluxWithin(r.gpu.texels, r.gpu.map, r.focus, radius, 1);
    const double ref = fluxWithin(r.blurred, r.gpu.map, r.focus, radius, 1);
    const double gpuSmooth = fluxWithin(a.gpu.texels, a.gpu.map, a.focus, radius, 1);
    std::printf("  within %.2f m of the focus: GPU %.5f trace %.5f (smooth GPU %.5f)\n", radius,
                gpu, ref, gpuSmooth);
    EXPECT_NEAR(gpu / ref, 1.0, 0.1) << radius;
    if (radius <= 0.1) {
      EXPECT_LT(gpu, 0.8 * gpuSmooth) << radius;  // roughness spreads the focus
    }
  }
}

TEST_F(PostfxObjectCausticsMaterialTest, DispersionSeparatesTheChannelsWithTheFeatureOn) {
  // Beyond the paraxial focus (the plane), the channel with the lower IOR (red) focuses later,
  // nearer the plane, so more of its light lands near the focus than blue's. Dispersion 2
  // (rutile) makes the spread measurable.
  SphereCaster sphere = reportSphere();
  sphere.dispersion = 2.0;
  const SphereComparison on = compareSphere(sphere, kReportSun, postfx::Feature::Dispersion);
  const SphereComparison off = compareSphere(sphere, kReportSun);
  const double radius = 0.1;
  glm::dvec3 gpu(0.0), ref(0.0), gpuOff(0.0);
  for (int c = 0; c < 3; ++c) {
    gpu[c] = fluxWithin(on.gpu.texels, on.gpu.map, on.focus, radius, c);
    ref[c] = fluxWithin(on.blurred, on.gpu.map, on.focus, radius, c);
    gpuOff[c] = fluxWithin(off.gpu.texels, off.gpu.map, off.focus, radius, c);
  }
  std::printf(
      "dispersion 2: flux within %.2f m of the focus GPU (%.4f %.4f %.4f) trace (%.4f "
      "%.4f %.4f); without Feature::Dispersion (%.4f %.4f %.4f)\n",
      radius, gpu.r, gpu.g, gpu.b, ref.r, ref.g, ref.b, gpuOff.r, gpuOff.g, gpuOff.b);
  EXPECT_GT(gpu.r, 1.2 * gpu.b);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(gpu[c] / ref[c], 1.0, 0.1) << "channel " << c;
    EXPECT_NEAR(on.gpuFlux[c] / on.refFlux[c], 1.0, 0.05) << "channel " << c;
  }
  // Off: one IOR, the channels identical.
  EXPECT_NEAR(gpuOff.r / gpuOff.b, 1.0, 1e-6);
}

TEST_F(PostfxObjectCausticsMaterialTest, EveryGlassFieldIsValidated) {
  const ObjectHost host(sunAt(0.0, 0.0));
  const GlMesh cube = makeCubeMesh(kCubeHalf);
  auto fx = makeObjectContext();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Case {
    const char* field;
    void (*apply)(postfx::CasterMaterial&, float);
    float value;
  };
  const Case cases[] = {
      {"transmission", [](postfx::CasterMaterial& m, float v) { m.transmission = v; }, -0.1f},
      {"transmission", [](postfx::CasterMaterial& m, float v) { m.transmission = v; }, nan},
      {"tint", [](postfx::CasterMaterial& m, float v) { m.tint.g = v; }, 1.5f},
      {"tint", [](postfx::CasterMaterial& m, float v) { m.tint.b = v; }, nan},
      {"roughness", [](postfx::CasterMaterial& m, float v) { m.roughness = v; }, 1.01f},
      {"roughness", [](postfx::CasterMaterial& m, float v) { m.roughness = v; }, nan},
      {"dispersion", [](postfx::CasterMaterial& m, float v) { m.dispersion = v; },
       postfx::kMaxCasterDispersion * 1.01f},
      {"dispersion", [](postfx::CasterMaterial& m, float v) { m.dispersion = v; }, -1.0f},
  };
  for (const Case& c : cases) {
    postfx::CasterMaterial m;
    c.apply(m, c.value);
    const postfx::CasterMesh caster = cube.caster(translation(kCubeCentre), m);
    EXPECT_EQ(postfx::dispatch(*fx, host.frame(&caster, 1, cubeSettings())),
              Result::InvalidArgument)
        << c.field << " " << c.value;
    EXPECT_NE(std::string(postfx::lastError(fx.get())).find(std::string("material.") + c.field),
              std::string::npos)
        << postfx::lastError(fx.get());
  }
  // The limits themselves are accepted.
  postfx::CasterMaterial edge;
  edge.transmission = 0.0f;
  edge.tint = glm::vec3(0.0f);
  edge.roughness = 1.0f;
  edge.dispersion = postfx::kMaxCasterDispersion;
  edge.thinWalled = true;
  const postfx::CasterMesh caster = cube.caster(translation(kCubeCentre), edge);
  EXPECT_EQ(postfx::dispatch(*fx, host.frame(&caster, 1, cubeSettings())), Result::Ok)
      << postfx::lastError(fx.get());
}

}  // namespace
