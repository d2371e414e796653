#include "godrays_pass.h"

#include <glkit/texture.h>

#include "godrays_constants.h"
#include "host_target.h"

#include "shader_library.h"

namespace postfx::detail {
namespace {

bool build(const std::string& defines, const char* fragment, const char* label, glkit::Program& out,
           std::string& error) {
  GLuint program = 0;
  if (!glkit::buildProgram(
          shaderLibrary(),
          {{GL_VERTEX_SHADER, "postfx/fullscreen.vert"}, {GL_FRAGMENT_SHADER, fragment}}, defines,
          label, program, error))
    return false;
  out = glkit::Program(program);
  return true;
}

}  // namespace

GodRaysPass::~GodRaysPass() {
  release();
}

Result GodRaysPass::init(const std::string& defines, std::string& error) {
  release();
  if (!build(defines + "#define POSTFX_GODRAYS_REDUCED 0\n", "postfx/godrays.frag",
             "postfx.god_rays", full_, error) ||
      !build(defines + "#define POSTFX_GODRAYS_REDUCED 1\n", "postfx/godrays.frag",
             "postfx.god_rays.reduced", reduced_, error) ||
      !build(defines, "postfx/godrays_upsample.frag", "postfx.god_rays.upsample", upsample_,
             error)) {
    release();
    return Result::ShaderCompileFailed;
  }
  glCreateFramebuffers(1, &framebuffer_);
  glkit::label(GL_FRAMEBUFFER, framebuffer_, "postfx.god_rays.framebuffer");
  glCreateFramebuffers(1, &reducedFramebuffer_);
  glkit::label(GL_FRAMEBUFFER, reducedFramebuffer_, "postfx.god_rays.reduced_framebuffer");
  glCreateBuffers(1, &uniformBuffer_);
  glNamedBufferStorage(uniformBuffer_, sizeof(shared::GodRaysBlock), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glkit::label(GL_BUFFER, uniformBuffer_, "postfx.god_rays.block");
  reducedSampler_ = glkit::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE,
                                         "postfx.sampler.god_rays_reduced");
  return Result::Ok;
}

void GodRaysPass::release() {
  full_ = glkit::Program();
  reduced_ = glkit::Program();
  upsample_ = glkit::Program();
  if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
  if (reducedFramebuffer_ != 0) glDeleteFramebuffers(1, &reducedFramebuffer_);
  if (uniformBuffer_ != 0) glDeleteBuffers(1, &uniformBuffer_);
  if (reducedTexture_ != 0) glDeleteTextures(1, &reducedTexture_);
  if (reducedSampler_ != 0) glDeleteSamplers(1, &reducedSampler_);
  framebuffer_ = reducedFramebuffer_ = uniformBuffer_ = reducedTexture_ = reducedSampler_ = 0;
  reducedWidth_ = reducedHeight_ = 0;
}

void GodRaysPass::ensureReduced(int w, int h) {
  if (reducedTexture_ != 0 && reducedWidth_ == w && reducedHeight_ == h) return;
  if (reducedTexture_ != 0) glDeleteTextures(1, &reducedTexture_);
  // RGBA16F rather than R11F_G11F_B10F: alpha carries each texel's distance for the upsample.
  glCreateTextures(GL_TEXTURE_2D, 1, &reducedTexture_);
  glTextureStorage2D(reducedTexture_, 1, GL_RGBA16F, w, h);
  glkit::label(GL_TEXTURE, reducedTexture_, "postfx.god_rays.reduced");
  glNamedFramebufferTexture(reducedFramebuffer_, GL_COLOR_ATTACHMENT0, reducedTexture_, 0);
  reducedWidth_ = w;
  reducedHeight_ = h;
}

Result GodRaysPass::prepare(const FrameDesc& frame, int width, int height,
                            const shared::GodRaysBlock& block, std::string& error) {
  const GodRayResolution resolution = frame.godRays.resolution;
  if (resolution != GodRayResolution::Full) {
    ensureReduced(godRayReducedSize(width, resolution), godRayReducedSize(height, resolution));
    // An allocation the driver refused leaves the march framebuffer incomplete: found here,
    // before anything is drawn.
    if (glCheckNamedFramebufferStatus(reducedFramebuffer_, GL_DRAW_FRAMEBUFFER) !=
        GL_FRAMEBUFFER_COMPLETE) {
      error = "godRays: the reduced-resolution march texture could not be allocated";
      return Result::OutOfMemory;
    }
  }
  if (!attachHostTarget(framebuffer_, frame.target.texture, "god-ray", error)) {
    finish();
    return Result::GlError;
  }
  glNamedBufferSubData(uniformBuffer_, 0, sizeof(block), &block);
  return Result::Ok;
}

void GodRaysPass::draw(const FrameDesc& frame, int width, int height) {
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_GODRAYS_BLOCK_BINDING, uniformBuffer_);
  if (frame.godRays.resolution == GodRayResolution::Full) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    glUseProgram(full_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return;
  }
  // March at reduced size, unblended: every texel is written (light and distance).
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, reducedFramebuffer_);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(reducedWidth_),
                     static_cast<float>(reducedHeight_));
  glDisablei(GL_BLEND, 0);
  glUseProgram(reduced_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Upsample, added into the target.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height));
  glEnablei(GL_BLEND, 0);
  glBindTextureUnit(kReducedUnit, reducedTexture_);
  glBindSampler(kReducedUnit, reducedSampler_);
  glUseProgram(upsample_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GodRaysPass::finish() {
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace postfx::detail
