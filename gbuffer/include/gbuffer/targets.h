#pragma once
// The G-buffer a deferred host renders into, in the formats the plugin reads:
//   depth   GL_DEPTH_COMPONENT32F (reverse-Z recommended, see DepthConvention)
//   normal  GL_RG16_SNORM, octahedral world-space normal (NormalEncoding::Octahedral)
//   albedo  GL_SRGB8_ALPHA8, linear albedo in rgb
//   hdr     GL_RGBA16F, the lit scene in linear light (the plugin adds into it)
#include <epoxy/gl.h>

#include <string>

namespace gbuffer {

enum class TargetError { None, ZeroSize, TooLarge, Incomplete };

class Targets {
 public:
  Targets() = default;
  Targets(const Targets&) = delete;
  Targets& operator=(const Targets&) = delete;
  ~Targets();

  // (Re)allocates every target at width x height. On error nothing is allocated and `error`
  // says why; a size equal to the current one is a no-op.
  TargetError resize(int width, int height, std::string& error);
  void release();

  int width() const { return width_; }
  int height() const { return height_; }
  GLuint depth() const { return depth_; }
  GLuint normal() const { return normal_; }
  GLuint albedo() const { return albedo_; }
  GLuint hdr() const { return hdr_; }
  // Framebuffer writing normal (0), albedo (1) with depth: the geometry pass.
  GLuint geometryFramebuffer() const { return geometryFbo_; }
  // Framebuffer writing hdr (0) with depth attached read-only in use: the lighting passes.
  GLuint lightingFramebuffer() const { return lightingFbo_; }

 private:
  int width_ = 0, height_ = 0;
  GLuint depth_ = 0, normal_ = 0, albedo_ = 0, hdr_ = 0;
  GLuint geometryFbo_ = 0, lightingFbo_ = 0;
};

}  // namespace gbuffer
