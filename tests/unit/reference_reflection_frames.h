#pragma once
// Frames for the traced reference's reflected-light tests: quads of any orientation, a camera
// looking any way (its G-buffer ray cast like reference_test_frames.h's lookDown), and the
// Fresnel averages a sine wave's reflected and refracted light must have.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"
#include "reference_test_surfaces.h"
#include "seabed_reference.h"

namespace referencetest {

using namespace ocean::reference;

// The quad a, b, c, d (corners in order) with one normal everywhere.
inline TriangleMesh quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                         const glm::dvec3& d, const glm::dvec3& normal) {
  TriangleMesh m;
  m.positions = {a, b, c, d};
  m.normals.assign(4, glm::normalize(normal));
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// Horizontal rectangle [x0, x1] x [z0, z1] at height y facing down (an underside, a ceiling).
inline TriangleMesh ceiling(double x0, double x1, double z0, double z1, double y) {
  return quad({x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}, {0.0, -1.0, 0.0});
}

// A camera at `eye` looking along `forward` with `up` (both unit, perpendicular), a field of
// view `fovY`, and its G-buffer rendered by ray casting `meshes`.
inline FrameReceivers look(const std::vector<TriangleMesh>& meshes, const glm::dvec3& eye,
                           const glm::dvec3& forward, const glm::dvec3& up, int width, int height,
                           double fovY, double level = 0.0) {
  std::string error;
  const auto scene = EmbreeScene::create(meshes, eye, error);
  EXPECT_TRUE(scene) << error;
  const glm::dvec3 right = glm::cross(forward, up);
  const glm::dmat3 viewToWorld(right, up, -forward);
  const double f = 1.0 / std::tan(0.5 * fovY);
  const glm::dvec4 projection(f * height / width, f, 0.0, 0.0);
  const size_t n = static_cast<size_t>(width) * height;
  std::vector<glm::dvec3> view(n), normals(n);
  std::vector<std::uint8_t> sky(n, 1);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t i = static_cast<size_t>(y) * width + x;
      const double ndcX = (x + 0.5) / width * 2.0 - 1.0, ndcY = (y + 0.5) / height * 2.0 - 1.0;
      const glm::dvec3 dirView(ndcX / projection.x, ndcY / projection.y, -1.0);
      const glm::dvec3 dir = glm::normalize(viewToWorld * dirView);
      RayHit hit;
      if (!scene->intersect(glm::dvec3(0.0), dir, 0.0, 1e30, hit)) continue;
      view[i] = glm::transpose(viewToWorld) * (dir * hit.t);
      normals[i] = hit.normal;
      sky[i] = 0;
    }
  }
  return makeFrameReceivers(width, height, eye, glm::transpose(viewToWorld), projection, level,
                            view, normals, sky);
}

struct View {
  glm::dvec3 eye{0.0}, forward{0.0, -1.0, 0.0}, up{0.0, 0.0, -1.0};
  int width = 48, height = 32;
  double fovY = 0.9;
  // Width of the view (m) on a plane facing it `distance` away.
  double widthAt(double distance) const {
    return 2.0 * distance * std::tan(0.5 * fovY) * width / height;
  }
};

struct TracedView {
  FrameReceivers receivers;
  FrameTraceResult result;
};

inline TracedView traceView(const Surface& water, const std::vector<TriangleMesh>& meshes,
                            const View& view, const FrameTraceDesc& desc) {
  TracedView t{look(meshes, view.eye, view.forward, view.up, view.width, view.height, view.fovY),
               {}};
  std::string error;
  const auto scene = EmbreeScene::create(meshes, view.eye, error);
  EXPECT_TRUE(scene) << error;
  t.result = traceFrameCaustics(water, *scene, t.receivers, desc);
  const FrameTraceResult& r = t.result;
  std::printf(
      "traced %d x %d: %zu lit, %zu mirror-lit pixels, %llu photons (%llu reflected per batch) in "
      "%d batches, reflected noise median %.4f p99 %.4f max %.4f, %.2f s\n",
      view.width, view.height, r.litPixels, r.reflectedLitPixels,
      static_cast<unsigned long long>(r.photons),
      static_cast<unsigned long long>(r.reflectedPhotonsPerBatch), r.batches,
      r.reflectedNoiseMedian, r.reflectedNoiseQuantile, r.reflectedNoiseMax, r.seconds);
  return t;
}

inline FrameTraceDesc reflectedDesc(const glm::dvec3& towardSun) {
  FrameTraceDesc desc;
  desc.towardSun = glm::normalize(towardSun);
  desc.ior = 1.333;
  desc.threads = 2;
  desc.reflected = true;
  return desc;
}

// The mean reflected and refracted light of a wave with crests along z (slopes in x only) over
// whole periods, each relative to flat water's: the sun's beam brings 1 per horizontal area of
// the mean plane, which reaches the surface at x where u = x - s h(x) (s = sun.x / sun.y), so
// surface point x gets the share du/dx = 1 - s h'(x) of the beam, split by the local Fresnel
// factors R + T = 1.
struct FresnelMeans {
  double reflected = 0.0, transmitted = 0.0;
};

inline FresnelMeans meanFresnelRatios(const Surface& surface, double period,
                                      const glm::dvec3& towardSun, double ior) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  const double s = sun.x / sun.y;
  double r = 0.0, t = 0.0, beam = 0.0;
  const int samples = 200000;
  for (int i = 0; i < samples; ++i) {
    const double slope = surface.sample((i + 0.5) / samples * period, 0.0).slopeX;
    const double share = 1.0 - s * slope;
    const double c = glm::dot(sun, glm::normalize(glm::dvec3(-slope, 1.0, 0.0)));
    r += share * fresnelReflectance(c, ior);
    t += share * fresnelTransmittance(c, ior);
    beam += share;
  }
  return {r / beam / fresnelReflectance(sun.y, ior), t / beam / fresnelTransmittance(sun.y, ior)};
}

}  // namespace referencetest
