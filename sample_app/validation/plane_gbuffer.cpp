#include "plane_gbuffer.h"

#include <cmath>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace ocean::validation {
namespace {

constexpr double kNear = 0.1;

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
  v.windowDepth = float(kNear / distance);
  return v;
}

PlaneView topDownView(int width, int height, double floorDistance) {
  return planeView(width, height, floorDistance, glm::dvec3(0.0, 1.0, 0.0),
                   glm::dvec3(0.0, 0.0, -1.0));
}

PlaneGbuffer::PlaneGbuffer(int width, int height, float windowDepth, const glm::vec3& normal) {
  const size_t pixels = size_t(width) * size_t(height);
  for (glkit::Texture& texture : textures_) texture = glkit::createTexture(GL_TEXTURE_2D, {});
  glTextureStorage2D(depth(), 1, GL_DEPTH_COMPONENT32F, width, height);
  glTextureStorage2D(this->normal(), 1, GL_RGBA16F, width, height);
  glTextureStorage2D(albedo(), 1, GL_RGBA8, width, height);
  const std::vector<float> depths(pixels, windowDepth);
  glTextureSubImage2D(depth(), 0, 0, 0, width, height, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
  const float n[4] = {normal.x, normal.y, normal.z, 0.0f}, white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  glClearTexImage(this->normal(), 0, GL_RGBA, GL_FLOAT, n);
  glClearTexImage(albedo(), 0, GL_RGBA, GL_FLOAT, white);
}

}  // namespace ocean::validation
