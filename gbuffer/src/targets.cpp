#include <gbuffer/targets.h>

#include <glkit/program.h>
#include <glkit/texture.h>

namespace gbuffer {
namespace {

// Nearest: the G-buffer is read texel-exact; filtering depth or normals across edges is wrong.
GLuint makeTexture(GLenum format, int width, int height, const char* name) {
  return glkit::createTexture2D(format, width, height, GL_NEAREST, name);
}

}  // namespace

Targets::~Targets() {
  release();
}

void Targets::release() {
  const GLuint textures[] = {depth_, normal_, albedo_, hdr_};
  for (GLuint texture : textures) {
    if (texture != 0) glDeleteTextures(1, &texture);
  }
  if (geometryFbo_ != 0) glDeleteFramebuffers(1, &geometryFbo_);
  if (lightingFbo_ != 0) glDeleteFramebuffers(1, &lightingFbo_);
  depth_ = normal_ = albedo_ = hdr_ = geometryFbo_ = lightingFbo_ = 0;
  width_ = height_ = 0;
}

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
  release();
  depth_ = makeTexture(GL_DEPTH_COMPONENT32F, width, height, "gbuffer.depth");
  normal_ = makeTexture(GL_RG16_SNORM, width, height, "gbuffer.normal");
  albedo_ = makeTexture(GL_SRGB8_ALPHA8, width, height, "gbuffer.albedo");
  hdr_ = makeTexture(GL_RGBA16F, width, height, "gbuffer.hdr");

  glCreateFramebuffers(1, &geometryFbo_);
  glNamedFramebufferTexture(geometryFbo_, GL_COLOR_ATTACHMENT0, normal_, 0);
  glNamedFramebufferTexture(geometryFbo_, GL_COLOR_ATTACHMENT1, albedo_, 0);
  glNamedFramebufferTexture(geometryFbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
  const GLenum geometryBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glNamedFramebufferDrawBuffers(geometryFbo_, 2, geometryBuffers);
  glkit::label(GL_FRAMEBUFFER, geometryFbo_, "gbuffer.geometry");

  glCreateFramebuffers(1, &lightingFbo_);
  glNamedFramebufferTexture(lightingFbo_, GL_COLOR_ATTACHMENT0, hdr_, 0);
  glNamedFramebufferTexture(lightingFbo_, GL_DEPTH_ATTACHMENT, depth_, 0);
  glkit::label(GL_FRAMEBUFFER, lightingFbo_, "gbuffer.lighting");

  const GLuint fbos[] = {geometryFbo_, lightingFbo_};
  for (GLuint fbo : fbos) {
    if (glCheckNamedFramebufferStatus(fbo, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      release();
      error = "G-buffer framebuffer incomplete";
      return TargetError::Incomplete;
    }
  }
  width_ = width;
  height_ = height;
  return TargetError::None;
}

}  // namespace gbuffer
