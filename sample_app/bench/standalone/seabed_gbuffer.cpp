#include "seabed_gbuffer.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace postfx::bench {
namespace {

// Dunes and ripples: 4-9 m below the water level at y = 0.
double seabedHeight(double x, double z) {
  return -6.5 + 1.6 * std::sin(0.21 * x + 0.4) * std::cos(0.17 * z) +
         0.6 * std::sin(0.9 * x - 0.5 * z) + 0.08 * std::sin(4.1 * x + 2.3 * z);
}

SeabedView seabedView(int width, int height) {
  SeabedView v;
  v.view = glm::lookAt(glm::dvec3(0.0), glm::dvec3(0.0, -std::tan(glm::radians(20.0)), -1.0),
                       glm::dvec3(0.0, 1.0, 0.0));
  v.projection = glm::perspectiveRH_ZO(glm::radians(60.0), double(width) / height, 0.1, 200.0);
  return v;
}

ocean::validation::SyntheticScene seabedScene(int width, int height, const SeabedView& view) {
  ocean::validation::SyntheticScene scene;
  scene.width = width;
  scene.height = height;
  scene.view = view.view;
  scene.projection = view.projection;
  scene.depthConvention = 1;
  scene.normalEncoding = 1;
  scene.albedoFormat = GL_RGBA8;
  scene.targetFormat = GL_RGBA16F;
  scene.skyAlbedo = glm::vec4(0.0f);
  ocean::validation::SyntheticSurface seabed;
  seabed.kind = ocean::validation::SyntheticSurface::Kind::HeightField;
  const glm::dvec3 eye = view.eye;  // the builder works relative to the camera
  seabed.height = [eye](double x, double z) { return seabedHeight(x + eye.x, z + eye.z) - eye.y; };
  seabed.albedo = glm::vec3(204.0f, 190.0f, 150.0f) / 255.0f;
  scene.surfaces.push_back(seabed);
  scene.maxDistance = 80.0;  // nothing beyond: the sky
  return scene;
}

}  // namespace

SeabedGbuffer::SeabedGbuffer(int width, int height)
    : view_(seabedView(width, height)), gbuffer_(seabedScene(width, height, view_)) {}

}  // namespace postfx::bench
