#include "plane_gbuffer.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace ocean::validation {
namespace {

constexpr double kNear = 0.1;

SyntheticScene planeScene(int width, int height, const PlaneView& view) {
  SyntheticScene scene;
  scene.width = width;
  scene.height = height;
  scene.view = view.view;
  scene.projection = view.projection;
  scene.depthConvention = 0;
  scene.normalEncoding = 1;
  scene.albedoFormat = GL_RGBA8;
  SyntheticSurface plane;
  plane.point = -view.normal * view.distance;
  plane.normal = view.normal;
  scene.surfaces.push_back(plane);
  return scene;
}

}  // namespace

PlaneView planeView(int width, int height, double distance, const glm::dvec3& normal,
                    const glm::dvec3& imageUp) {
  PlaneView v;
  v.aspect = double(width) / double(height);
  v.focal = 1.0 / std::tan(glm::radians(30.0));  // 60 degree vertical field of view
  v.view = glm::lookAt(glm::dvec3(0.0), -normal, imageUp);
  v.projection = glm::dmat4(0.0);  // reverse-Z, infinite far plane: window depth = near / distance
  v.projection[0][0] = v.focal / v.aspect;
  v.projection[1][1] = v.focal;
  v.projection[2][3] = -1.0;
  v.projection[3][2] = kNear;
  v.normal = normal;
  v.distance = distance;
  return v;
}

PlaneView topDownView(int width, int height, double floorDistance) {
  return planeView(width, height, floorDistance, glm::dvec3(0.0, 1.0, 0.0),
                   glm::dvec3(0.0, 0.0, -1.0));
}

PlaneGbuffer::PlaneGbuffer(int width, int height, const PlaneView& view)
    : gbuffer_(planeScene(width, height, view)) {}

}  // namespace ocean::validation
