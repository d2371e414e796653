#pragma once
// The sun's shadow map: orthographic along the light as it travels under water (refracted),
// fitted to a square around the camera and snapped to texels so shadows do not swim.
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <glkit/handle.h>

namespace ocean {

class ShadowMap {
 public:
  void create(int size);
  // Fits the light's view-projection around the camera with half-extent `radius` metres, depth
  // [0,1] forward; toLight is unit. Returns world -> light clip in double (world translation
  // included); relativeTo() rebases it onto a camera for float shaders.
  glm::dmat4 fit(const glm::dvec3& cameraPosition, const glm::vec3& toLight, double radius) const;
  static glm::mat4 relativeTo(const glm::dmat4& worldToClip, const glm::dvec3& cameraPosition);
  int size() const { return size_; }
  GLuint texture() const { return texture_.id(); }
  GLuint framebuffer() const { return framebuffer_.id(); }

 private:
  int size_ = 0;
  glkit::Texture texture_;
  glkit::Framebuffer framebuffer_;
};

}  // namespace ocean
