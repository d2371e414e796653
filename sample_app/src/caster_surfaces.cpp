#include "caster_surfaces.h"

#include <glkit/texture.h>

namespace ocean_sample {
const glkit::ShaderLibrary& shaderLibrary();
}

namespace ocean {
namespace {

glkit::Program buildForward(const char* fragment, const char* label, std::string& error) {
  return glkit::buildProgram(
      ocean_sample::shaderLibrary(),
      {{GL_VERTEX_SHADER, "sample/geometry.vert"}, {GL_FRAGMENT_SHADER, fragment}}, "", label,
      error);
}

}  // namespace

bool CasterSurfaces::create(const GpuScene& scene, int width, int height, std::string& error) {
  width_ = width;
  height_ = height;
  if (scene.has(GpuScene::DrawSet::Metal)) {
    metal_ = buildForward("sample/metal_surface.frag", "sample.metal_surface", error);
    if (metal_.id() == 0) return false;
  }
  if (!scene.has(GpuScene::DrawSet::Refractive)) return true;
  glassBack_ = buildForward("sample/glass_back_faces.frag", "sample.glass_back_faces", error);
  if (glassBack_.id() == 0) return false;
  glass_ = buildForward("sample/glass_surface.frag", "sample.glass_surface", error);
  if (glass_.id() == 0) return false;
  backFaces_ = glkit::createTexture2D(GL_RGBA16F, width, height, GL_NEAREST, "sample.glass_back");
  backDepth_ = glkit::createTexture2D(GL_DEPTH_COMPONENT32F, width, height, GL_NEAREST,
                                      "sample.glass_back_depth");
  backFbo_ = glkit::createFramebuffer("sample.glass_back");
  glNamedFramebufferTexture(backFbo_.id(), GL_COLOR_ATTACHMENT0, backFaces_.id(), 0);
  glNamedFramebufferTexture(backFbo_.id(), GL_DEPTH_ATTACHMENT, backDepth_.id(), 0);
  if (glCheckNamedFramebufferStatus(backFbo_.id(), GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
    error = "glass back-face framebuffer incomplete";
    glass_ = {};
    return false;
  }
  return true;
}

void CasterSurfaces::drawMetal(const GpuScene& scene, const glm::dvec3& eye,
                               GLuint shadowMap) const {
  if (metal_.id() == 0) return;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.metal_surface");
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glUseProgram(metal_.id());
  glBindTextureUnit(3, shadowMap);
  scene.draw(metal_.id(), eye, GpuScene::DrawSet::Metal);
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  glDisable(GL_DEPTH_TEST);
  glPopDebugGroup();
}

void CasterSurfaces::drawGlass(const GpuScene& scene, const glm::dvec3& eye, GLuint frame,
                               GLuint frameCopy, GLuint frameFbo, GLuint sceneDepth,
                               GLuint shadowMap) const {
  if (glass_.id() == 0) return;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "sample.glass_surface");
  glEnable(GL_DEPTH_TEST);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_GREATER);  // reverse-Z: the nearest far side
  glBindFramebuffer(GL_FRAMEBUFFER, backFbo_.id());
  const float none[4] = {0, 0, 0, 0};
  glClearBufferfv(GL_COLOR, 0, none);
  const float far = 0.0f;
  glClearBufferfv(GL_DEPTH, 0, &far);
  glUseProgram(glassBack_.id());
  scene.draw(glassBack_.id(), eye, GpuScene::DrawSet::Refractive);

  glCopyImageSubData(frame, GL_TEXTURE_2D, 0, 0, 0, 0, frameCopy, GL_TEXTURE_2D, 0, 0, 0, 0, width_,
                     height_, 1);
  glBindFramebuffer(GL_FRAMEBUFFER, frameFbo);
  glUseProgram(glass_.id());
  const GLuint inputs[] = {frameCopy, sceneDepth, backFaces_.id(), shadowMap};
  glBindTextures(0, 4, inputs);
  scene.draw(glass_.id(), eye, GpuScene::DrawSet::Refractive);
  glBindTextures(0, 4, nullptr);
  glDisable(GL_DEPTH_TEST);
  glPopDebugGroup();
}

}  // namespace ocean
