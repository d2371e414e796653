#pragma once
// Frames with known answers for the traced frame reference's tests: a camera looking straight
// down at ray-cast triangles, and a trace of it with its statistics printed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"

namespace referencetest {

using namespace ocean::reference;

// Axis-aligned horizontal rectangle [x0, x1] x [z0, z1] at height y, normal up.
inline TriangleMesh horizontalQuad(double x0, double x1, double z0, double z1, double y) {
  TriangleMesh m;
  m.positions = {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
  m.normals.assign(4, glm::dvec3(0.0, 1.0, 0.0));
  m.triangles = {{0, 2, 1}, {0, 3, 2}};
  return m;
}

// A camera at `eye` looking straight down (view -z = world -y, view up = world -z), with a
// square field of view `fovY`, and its G-buffer rendered by ray casting `scene`.
inline FrameReceivers lookDown(const std::vector<TriangleMesh>& meshes, const glm::dvec3& eye,
                               int width, int height, double fovY, double level = 0.0) {
  std::string error;
  const auto scene = EmbreeScene::create(meshes, eye, error);
  EXPECT_TRUE(scene) << error;
  const glm::dvec3 right(1, 0, 0), up(0, 0, -1), back(0, 1, 0);
  const glm::dmat3 viewToWorld(right, up, back);
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

struct Traced {
  FrameReceivers receivers;
  FrameTraceResult result;
};

inline Traced trace(const Surface& water, const std::vector<TriangleMesh>& meshes,
                    const glm::dvec3& eye, FrameTraceDesc desc, int width = 48, int height = 32,
                    double fovY = 0.9) {
  Traced t{lookDown(meshes, eye, width, height, fovY), {}};
  std::string error;
  const auto scene = EmbreeScene::create(meshes, eye, error);
  EXPECT_TRUE(scene) << error;
  t.result = traceFrameCaustics(water, *scene, t.receivers, desc);
  std::printf(
      "traced %d x %d: %zu lit pixels, %llu photons in %d batches, noise median %.4f p99 %.4f "
      "max %.4f, %.2f s\n",
      width, height, t.result.litPixels, static_cast<unsigned long long>(t.result.photons),
      t.result.batches, t.result.noiseMedian, t.result.noiseQuantile, t.result.noiseMax,
      t.result.seconds);
  return t;
}

inline FrameTraceDesc baseDesc(const glm::dvec3& towardSun) {
  FrameTraceDesc desc;
  desc.towardSun = glm::normalize(towardSun);
  desc.ior = 1.333;
  desc.threads = 2;
  return desc;
}

}  // namespace referencetest
