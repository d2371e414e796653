// The traced frame reference's object caustics (FrameTraceDesc::casters): light through glass
// and off metal, on real triangles, against answers known without the frame: the exact sphere
// trace's flux (object_caustics_reference.h) for a dense and an index-below-water sphere, an
// index-matched sphere that refills its own shadow, a mirror that sends flat water's light on
// unchanged, a point light's caustic through the sphere against the exact trace from a light,
// and the same bits for any thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "object_caustics_local_light.h"
#include "object_caustics_reference.h"
#include "object_caustics_scene.h"
#include "reference_test_frames.h"
#include "reference_test_surfaces.h"

namespace {

using namespace ocean::reference;
using referencetest::baseDesc;
using referencetest::FlatSurface;
using referencetest::horizontalQuad;
using referencetest::kPi;
using referencetest::trace;
using referencetest::Traced;

constexpr double kPlaneY = -4.0;
const glm::dvec3 kEye(0.0, -0.5, 0.0);
constexpr int kWidth = 96, kHeight = 64;
constexpr double kFovY = 0.9;

// The shared UV sphere (object_caustics_scene.h) as a traced mesh around `centre`.
TriangleMesh sphereMesh(const glm::dvec3& centre, double radius, int slices, int stacks) {
  const UvSphere sphere = uvSphere(radius, slices, stacks);
  TriangleMesh m;
  for (const glm::dvec3& p : sphere.positions) m.positions.push_back(centre + p);
  m.normals = sphere.normals;
  for (size_t t = 0; t + 2 < sphere.indices.size(); t += 3)
    m.triangles.emplace_back(sphere.indices[t], sphere.indices[t + 1], sphere.indices[t + 2]);
  return m;
}

// The sun 45 degrees from the zenith, travelling toward +x: the sphere's shadow falls clear of
// the part of the plane the sphere hides from the camera above.
const glm::dvec3 kTowardSun = glm::normalize(glm::dvec3(-1.0, 1.0, 0.0));
const glm::dvec3 kSphereCentre(-1.0, -2.5, 0.0);
constexpr double kSphereRadius = 0.5;

postfx::CasterMaterial glass(float ior, glm::vec3 absorption = glm::vec3(0.0f)) {
  postfx::CasterMaterial m;
  m.ior = ior;
  m.absorption = absorption;
  return m;
}

struct SphereFrame {
  Traced traced;
  double objectFlux = 0.0;  // across the refracted beam, m^2 of the sun's irradiance (mean RGB)
  double upY = 1.0;
};

// The glass sphere over the plane under flat water, traced with the sphere as a caster.
SphereFrame traceSphere(const postfx::CasterMaterial& material, int threads = 2) {
  const FlatSurface water;
  FrameTraceDesc desc = baseDesc(kTowardSun);
  desc.threads = threads;
  desc.casters = {std::nullopt, material};
  SphereFrame s;
  s.traced = trace(
      water,
      {horizontalQuad(-50, 50, -50, 50, kPlaneY), sphereMesh(kSphereCentre, kSphereRadius, 96, 48)},
      kEye, desc, kWidth, kHeight, kFovY);
  s.upY = -refractSunRay(kTowardSun, 0.0, 0.0, desc.ior).y;
  // Each plane pixel's footprint (the plane is square to the view): E is flux per horizontal
  // area in units of flat water's, the launch's horizontal beam area; across the beam, times u.y.
  const FrameReceivers& r = s.traced.receivers;
  const double depth = kEye.y - kPlaneY;
  const double footprint = (2.0 * depth * std::tan(0.5 * kFovY)) *
                           (2.0 * depth * std::tan(0.5 * kFovY)) /
                           (static_cast<double>(kHeight) * kHeight);
  for (size_t i = 0; i < r.size(); ++i) {
    if (!r.valid[i] || std::abs(r.position[i].y + r.camera.y - kPlaneY) > 1e-6) continue;
    const glm::dvec3& e = s.traced.result.objectIrradiance[i];
    s.objectFlux += (e.x + e.y + e.z) / 3.0 * footprint * s.upY;
  }
  return s;
}

// The exact sphere trace (no frame, no kernel): flux through the sphere to the plane.
double exactSphereFlux(const postfx::CasterMaterial& material, double upY) {
  SphereCaster sphere;
  sphere.centre = kSphereCentre;
  sphere.radius = kSphereRadius;
  sphere.ior = double(material.ior) / 1.333;
  sphere.absorption = glm::dvec3(material.absorption);
  const glm::dvec3 up = -refractSunRay(kTowardSun, 0.0, 0.0, 1.333);
  EXPECT_NEAR(up.y, upY, 1e-12);
  postfx::ObjectCausticMap map;
  map.size = 8;
  map.axisU = {1.0, 0.0, 0.0};
  map.axisV = {0.0, 0.0, 1.0};
  const CausticReference exact = traceSphereReference(sphere, up, kPlaneY, map, 600);
  const glm::dvec3 flux = exact.fluxInMap + exact.fluxOutside;
  return (flux.x + flux.y + flux.z) / 3.0;
}

TEST(FrameReferenceCasters, GlassSphereFluxIsTheExactTracesAndABubbleDiffersAsItDoes) {
  // Solid glass (1.5) focuses: its light lands within the view and the frame's object light
  // carries the exact trace's flux. An index below the water's (1.0, an air bubble) reflects
  // its rim totally and spreads the rest, much of it beyond the view or under the sphere as the
  // camera sees it: no more than the exact flux, a peak below flat water's, as the exact trace
  // says (less than half the dense sphere's flux).
  double fluxes[2] = {0.0, 0.0}, exacts[2] = {0.0, 0.0}, peaks[2] = {0.0, 0.0};
  const float iors[2] = {1.5f, 1.0f};
  for (int k = 0; k < 2; ++k) {
    const postfx::CasterMaterial material = glass(iors[k], {0.02f, 0.1f, 0.3f});
    const SphereFrame s = traceSphere(material);
    exacts[k] = exactSphereFlux(material, s.upY);
    fluxes[k] = s.objectFlux;
    std::printf("IOR %.1f: frame object flux %.4f m^2, exact %.4f m^2 (%.2f %%), %zu shadow px\n",
                double(iors[k]), fluxes[k], exacts[k], 100.0 * (fluxes[k] / exacts[k] - 1.0),
                s.traced.result.casterShadowPixels);
    EXPECT_GT(s.traced.result.casterShadowPixels, 100u);
    for (const glm::dvec3& e : s.traced.result.objectIrradiance) {
      ASSERT_TRUE(std::isfinite(e.x) && std::isfinite(e.y) && std::isfinite(e.z));
      ASSERT_GE(std::min({e.x, e.y, e.z}), 0.0);
      peaks[k] = std::max(peaks[k], (e.x + e.y + e.z) / 3.0);
    }
  }
  EXPECT_NEAR(fluxes[0] / exacts[0], 1.0, 0.02) << "dense glass";
  EXPECT_LT(fluxes[1], 1.02 * exacts[1]) << "the bubble creates no light";
  EXPECT_LT(exacts[1], 0.6 * exacts[0]);
  EXPECT_LT(fluxes[1], 0.6 * fluxes[0]);
  EXPECT_GT(peaks[0], 2.0) << "dense glass focuses";
  EXPECT_LT(peaks[1], 1.0) << "a bubble spreads its light";
}

// The irradiance-weighted centroid and the brightest point of a caustic on the plane.
struct Focus {
  glm::dvec3 weighted{0.0}, brightest{0.0};
  double total = 0.0, peak = 0.0;
  void add(const glm::dvec3& p, double e) {
    weighted += e * p;
    total += e;
    if (e > peak) {
      peak = e;
      brightest = p;
    }
  }
  glm::dvec3 centroid() const { return weighted / total; }
};

TEST(FrameReferenceCasters, GlassSphereFocusesWhereTheExactTraceDoes) {
  // The caustic's centroid and brightest point on the plane: the frame against the exact sphere
  // trace binned on the same plane (2 cm bins). (The oblique plane cuts the converging beam
  // unevenly, so the centroid is not on the refracted ray through the centre.)
  const postfx::CasterMaterial material = glass(1.5f);
  const SphereFrame s = traceSphere(material);
  const glm::dvec3 down = refractSunRay(kTowardSun, 0.0, 0.0, 1.333);
  const glm::dvec3 axis = kSphereCentre + down * ((kPlaneY - kSphereCentre.y) / down.y);
  const FrameReceivers& r = s.traced.receivers;
  Focus frame;
  for (size_t i = 0; i < r.size(); ++i) {
    const glm::dvec3 p = r.position[i] + r.camera;
    if (!r.valid[i] || std::abs(p.y - kPlaneY) > 1e-6) continue;
    frame.add(p, s.traced.result.objectIrradiance[i].y);
  }
  ASSERT_GT(frame.total, 0.0);
  const glm::dvec3 centroid = frame.centroid(), brightest = frame.brightest;

  SphereCaster sphere;
  sphere.centre = kSphereCentre;
  sphere.radius = kSphereRadius;
  sphere.ior = 1.5 / 1.333;
  postfx::ObjectCausticMap bins;
  bins.size = 150;
  bins.origin = axis - glm::dvec3(1.5, 0.0, 1.5);
  bins.axisU = {3.0, 0.0, 0.0};
  bins.axisV = {0.0, 0.0, 3.0};
  const CausticReference exact = traceSphereReference(sphere, -down, kPlaneY, bins, 800);
  Focus traced;
  for (int j = 0; j < bins.size; ++j)
    for (int i = 0; i < bins.size; ++i)
      traced.add(
          bins.origin + (i + 0.5) / bins.size * bins.axisU + (j + 0.5) / bins.size * bins.axisV,
          exact.irradiance[static_cast<size_t>(j) * bins.size + i].y);
  ASSERT_GT(traced.total, 0.0);
  const glm::dvec3 exactCentroid = traced.centroid(), exactBrightest = traced.brightest;
  const double pixel = 2.0 * (kEye.y - kPlaneY) * std::tan(0.5 * kFovY) / kHeight;
  std::printf(
      "focus: centroid frame (%.3f, %.3f) exact (%.3f, %.3f); brightest frame (%.3f, "
      "%.3f) exact (%.3f, %.3f); pixel %.3f m\n",
      centroid.x, centroid.z, exactCentroid.x, exactCentroid.z, brightest.x, brightest.z,
      exactBrightest.x, exactBrightest.z, pixel);
  EXPECT_LT(glm::length(glm::dvec2(centroid.x - exactCentroid.x, centroid.z - exactCentroid.z)),
            0.25 * pixel);
  EXPECT_LT(glm::length(glm::dvec2(brightest.x - exactBrightest.x, brightest.z - exactBrightest.z)),
            1.5 * pixel);
}

TEST(FrameReferenceCasters, IndexMatchedSphereRefillsItsShadow) {
  // Glass of the water's own index bends nothing and reflects nothing: its light lands exactly
  // where its shadow is, so shadow + object light is flat water's light everywhere.
  const SphereFrame s = traceSphere(glass(1.333f));
  const FrameTraceResult& r = s.traced.result;
  const FrameReceivers& rec = s.traced.receivers;
  double worst = 0.0, mean = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < rec.size(); ++i) {
    if (!r.casterShadow[i] || std::abs(rec.position[i].y + rec.camera.y - kPlaneY) > 1e-6) continue;
    const double total = r.irradiance[i] + r.objectIrradiance[i].y;
    worst = std::max(worst, std::abs(total - 1.0));
    mean += total;
    ++count;
  }
  ASSERT_GT(count, 100u);
  mean /= static_cast<double>(count);
  std::printf("index-matched sphere: %zu shadow pixels, mean %.4f, worst |E - 1| %.4f\n", count,
              mean, worst);
  EXPECT_NEAR(mean, 1.0, 0.01);
  // Pixels at the shadow's edge take some of their kernel from outside it: a bound of a few
  // stated noises, not one.
  EXPECT_LT(worst, 4.0 * r.noiseQuantile + 0.05);
}

TEST(FrameReferenceCasters, PerfectMirrorSendsFlatWatersLightOnUnchanged) {
  // A vertical mirror (F0 = 1) facing the light: the reflected beam keeps its vertical
  // component, so the patch it lights on the plane gets exactly flat water's irradiance, 1.
  const FlatSurface water;
  FrameTraceDesc desc = baseDesc(kTowardSun);
  postfx::CasterMaterial mirror;
  mirror.type = postfx::CasterMaterialType::Reflective;
  mirror.reflectance = glm::vec3(1.0f);
  mirror.roughness = 0.0f;
  desc.casters = {std::nullopt, mirror};
  TriangleMesh quad;
  const double x = 0.6;
  quad.positions = {{x, -3.5, -0.6}, {x, -3.5, 0.6}, {x, -2.0, 0.6}, {x, -2.0, -0.6}};
  quad.normals.assign(4, glm::dvec3(-1.0, 0.0, 0.0));
  quad.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Traced t = trace(water, {horizontalQuad(-50, 50, -50, 50, kPlaneY), quad}, kEye, desc,
                         kWidth, kHeight, kFovY);
  const glm::dvec3 down = refractSunRay(kTowardSun, 0.0, 0.0, desc.ior);
  const double slope = down.x / -down.y;
  // The patch: the mirror's reflection of its own extent, shrunk by a kernel radius or two.
  const double x0 = x - (-2.0 - kPlaneY) * slope + 0.12, x1 = x - (-3.5 - kPlaneY) * slope - 0.12;
  double mean = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < t.receivers.size(); ++i) {
    const glm::dvec3 p = t.receivers.position[i] + t.receivers.camera;
    if (!t.receivers.valid[i] || std::abs(p.y - kPlaneY) > 1e-6) continue;
    if (p.x < x0 || p.x > x1 || std::abs(p.z) > 0.45) continue;
    mean += t.result.objectIrradiance[i].x;
    ++count;
    EXPECT_NEAR(t.result.objectIrradiance[i].x, 1.0, 4.0 * t.result.noiseQuantile);
  }
  ASSERT_GT(count, 20u);
  mean /= static_cast<double>(count);
  std::printf("mirror: %zu patch pixels, mean reflected E %.4f\n", count, mean);
  EXPECT_NEAR(mean, 1.0, 0.02);
}

TEST(FrameReferenceCasters, LocalLightThroughTheSphereCarriesTheExactFlux) {
  // A point light under the water beside the sphere, the sun below the horizon: the traced
  // light through the sphere (intensity x sr, absorbed by the water on both legs) is the exact
  // trace's from the light (object_caustics_local_light.h), and nothing else is lit.
  const FlatSurface water;
  FrameTraceDesc desc = baseDesc({0.0, 1.0, 0.0});
  desc.towardSun = glm::normalize(glm::dvec3(0.3, -1.0, 0.0));
  const postfx::CasterMaterial material = glass(1.5f, {0.02f, 0.1f, 0.3f});
  desc.casters = {std::nullopt, material};
  desc.waterAbsorption = {0.05, 0.1, 0.2};
  TracedLight light;
  light.position = {-2.2, -0.8, 0.0};
  light.spot = false;
  light.intensity = {30.0, 20.0, 10.0};
  desc.lights = {light};
  const Traced t = trace(
      water,
      {horizontalQuad(-50, 50, -50, 50, kPlaneY), sphereMesh(kSphereCentre, kSphereRadius, 96, 48)},
      kEye, desc, kWidth, kHeight, kFovY);
  const FrameTraceResult& r = t.result;
  ASSERT_EQ(r.localIrradiance.size(), t.receivers.size());
  EXPECT_EQ(r.litPixels, 0u) << "no sun";
  EXPECT_GT(r.casterShadowPixels, 100u);
  const double depth = kEye.y - kPlaneY;
  const double footprint = (2.0 * depth * std::tan(0.5 * kFovY)) *
                           (2.0 * depth * std::tan(0.5 * kFovY)) /
                           (static_cast<double>(kHeight) * kHeight);
  glm::dvec3 flux(0.0);
  for (size_t i = 0; i < t.receivers.size(); ++i) {
    ASSERT_EQ(r.irradiance[i], 0.0);
    ASSERT_EQ(r.objectIrradiance[i], glm::dvec3(0.0));
    if (!t.receivers.valid[i] ||
        std::abs(t.receivers.position[i].y + t.receivers.camera.y - kPlaneY) > 1e-6)
      continue;
    flux += r.localIrradiance[i] * footprint;
  }
  SphereCaster sphere;
  sphere.centre = kSphereCentre;
  sphere.radius = kSphereRadius;
  sphere.ior = double(material.ior) / 1.333;
  sphere.absorption = glm::dvec3(material.absorption);
  LocalLightSource source;
  source.position = light.position;
  source.intensity = light.intensity;
  const LocalCausticReference exact = traceSphereFromLight(
      sphere, source, floorBins(kSphereCentre, kPlaneY, 4.0, 8), desc.waterAbsorption, 600);
  const glm::dvec3 expected = exact.fluxInBins + exact.fluxOutside;
  std::printf("point light: frame flux (%.4f, %.4f, %.4f), exact (%.4f, %.4f, %.4f)\n", flux.x,
              flux.y, flux.z, expected.x, expected.y, expected.z);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(flux[c] / expected[c], 1.0, 0.03) << "channel " << c;
}

TEST(FrameReferenceCasters, ObjectLightIsTheSameForAnyThreadCount) {
  const postfx::CasterMaterial material = glass(1.5f, {0.02f, 0.1f, 0.3f});
  const SphereFrame one = traceSphere(material, 1), two = traceSphere(material, 2);
  ASSERT_EQ(one.traced.result.objectIrradiance.size(), two.traced.result.objectIrradiance.size());
  for (size_t i = 0; i < one.traced.result.objectIrradiance.size(); ++i)
    ASSERT_EQ(one.traced.result.objectIrradiance[i], two.traced.result.objectIrradiance[i]);
  EXPECT_EQ(one.traced.result.batches, two.traced.result.batches);
}

}  // namespace
