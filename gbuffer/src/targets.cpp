#include <gbuffer/targets.h>

#include <glkit/program.h>
#include <glkit/texture.h>

namespace gbuffer {
namespace {

// Nearest: the G-buffer is read texel-exact; filtering depth or normals across edges is wrong.
glkit::Texture makeTexture(GLenum format, int width, int height, const char* name) {
  return glkit::createTexture2D(format, width, height, GL_NEAREST, name);
}

}  // namespace

TargetError Targets::resize(int width, int height, std::string& error) {
  if (width <= 0 || height <= 0) {
    error = "render target size must be positive, got " + std::to_string(width) + "x" +
            std::to_string(height);
    return TargetError::ZeroSize;
  }
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (width > maxSize || height > maxSize) {
    error = "render target size " + std::to_string(width) + "x" + std::to_string(height) +
            " exceeds GL_MAX_TEXTURE_SIZE " + std::to_string(maxSize);
    return TargetError::TooLarge;
  }
  if (width == width_ && height == height_) return TargetError::None;
  *this = Targets();  // the old size goes first: never two of them allocated at once
  depth_ = makeTexture(GL_DEPTH_COMPONENT32F, width, height, "gbuffer.depth");
  normal_ = makeTexture(GL_RG16_SNORM, width, height, "gbuffer.normal");
  albedo_ = makeTexture(GL_SRGB8_ALPHA8, width, height, "gbuffer.albedo");
  hdr_ = makeTexture(GL_RGBA16F, width, height, "gbuffer.hdr");

  geometryFbo_ = glkit::createFramebuffer("gbuffer.geometry");
  const GLuint geometry = geometryFbo_.id();
  glNamedFramebufferTexture(geometry, GL_COLOR_ATTACHMENT0, normal_.id(), 0);
  glNamedFramebufferTexture(geometry, GL_COLOR_ATTACHMENT1, albedo_.id(), 0);
  glNamedFramebufferTexture(geometry, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
  const GLenum geometryBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(geometry, 2, geometryBuffers);

  lightingFbo_ = glkit::createFramebuffer("gbuffer.lighting");
  glNamedFramebufferTexture(lightingFbo_.id(), GL_COLOR_ATTACHMENT0, hdr_.id(), 0);
  glNamedFramebufferTexture(lightingFbo_.id(), GL_DEPTH_ATTACHMENT, depth_.id(), 0);

  for (GLuint fbo : {geometry, lightingFbo_.id()}) {
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      *this = Targets();
      error = "G-buffer framebuffer incomplete";
      return TargetError::Incomplete;
    }
  }
  width_ = width;
  height_ = height;
  return TargetError::None;
}

}  // namespace gbuffer
