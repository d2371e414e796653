#pragma once
// The G-buffer a deferred host renders into, in the formats the plugin reads:
//   depth   GL_DEPTH_COMPONENT32F (reverse-Z recommended, see DepthConvention)
//   normal  GL_RG16_SNORM, octahedral world-space normal (NormalEncoding::Octahedral)
//   albedo  GL_SRGB8_ALPHA8, linear albedo in rgb
//   hdr     GL_RGBA16F, the lit scene in linear light (the plugin adds into it)
#include <epoxy/gl.h>

#include <glkit/handle.h>

#include <string>

namespace gbuffer {

enum class TargetError { None, ZeroSize, TooLarge, Incomplete };

class Targets {
 public:
  // (Re)allocates every target at width x height. On error nothing is allocated and `error`
  // says why; a size equal to the current one is a no-op.
  TargetError resize(int width, int height, std::string& error);

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint depth() const { return depth_.id(); }
  GLuint normal() const { return normal_.id(); }
  GLuint albedo() const { return albedo_.id(); }
  GLuint hdr() const { return hdr_.id(); }
  // Framebuffer writing normal (0), albedo (1) with depth: the geometry pass.
  GLuint geometryFramebuffer() const { return geometryFbo_.id(); }
  // Framebuffer writing hdr (0) with depth attached read-only in use: the lighting passes.
  GLuint lightingFramebuffer() const { return lightingFbo_.id(); }

 private:
  int width_ = 0, height_ = 0;
  glkit::Texture depth_, normal_, albedo_, hdr_;
  glkit::Framebuffer geometryFbo_, lightingFbo_;
};

}  // namespace gbuffer
