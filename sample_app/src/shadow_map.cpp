#include "shadow_map.h"

#include <glm/gtc/matrix_transform.hpp>

#include <glkit/program.h>

namespace ocean {

void ShadowMap::create(int size) {
  size_ = size;
  texture_ = glkit::createTexture(GL_TEXTURE_2D, "sample.shadow_map");
  const GLuint texture = texture_.id();
  glTextureStorage2D(texture, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTextureParameteri(texture, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  framebuffer_ = glkit::createFramebuffer("sample.shadow_map");
  glNamedFramebufferTexture(framebuffer_.id(), GL_DEPTH_ATTACHMENT, texture, 0);
  glNamedFramebufferDrawBuffer(framebuffer_.id(), GL_NONE);
}

glm::dmat4 ShadowMap::fit(const glm::dvec3& cameraPosition, const glm::vec3& toLight,
                          double radius) const {
  const glm::dvec3 light = glm::normalize(glm::dvec3(toLight));
  const glm::dvec3 up = std::abs(light.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  // Snap the fitted centre to whole texels in light space, in double world coordinates, so the
  // map's texel grid is fixed in the world while the camera moves.
  const glm::dmat4 lightView = glm::lookAt(glm::dvec3(0.0), -light, up);
  const double texel = 2.0 * radius / size_;
  glm::dvec3 centre = glm::dvec3(lightView * glm::dvec4(cameraPosition, 1.0));
  centre.x = std::floor(centre.x / texel) * texel;
  centre.y = std::floor(centre.y / texel) * texel;
  const glm::dvec3 worldCentre = glm::dvec3(glm::inverse(lightView) * glm::dvec4(centre, 1.0));
  // The eye sits above the focus along the light.
  const glm::dvec3 eye = worldCentre + light * 200.0;
  const glm::dmat4 view = glm::lookAt(eye, eye - light, up);
  // Forward [0,1] depth (the sample sets ZERO_TO_ONE clip control for every pass).
  const glm::dmat4 projection = glm::orthoRH_ZO(-radius, radius, -radius, radius, 0.0, 400.0);
  return projection * view;
}

glm::mat4 ShadowMap::relativeTo(const glm::dmat4& worldToClip, const glm::dvec3& cameraPosition) {
  return glm::mat4(worldToClip * glm::translate(glm::dmat4(1.0), cameraPosition));
}

}  // namespace ocean
