#include "godrays_pass.h"

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
  if (!build(defines + "#define POSTFX_GODRAYS_HALF 0\n", "postfx/godrays.frag", "postfx.god_rays",
             full_, error) ||
      !build(defines + "#define POSTFX_GODRAYS_HALF 1\n", "postfx/godrays.frag",
             "postfx.god_rays.half", half_, error) ||
      !build(defines, "postfx/godrays_upsample.frag", "postfx.god_rays.upsample", upsample_,
             error)) {
    release();
    return Result::ShaderCompileFailed;
  }
  glCreateFramebuffers(1, &framebuffer_);
  glkit::label(GL_FRAMEBUFFER, framebuffer_, "postfx.god_rays.framebuffer");
  glCreateFramebuffers(1, &halfFramebuffer_);
  glkit::label(GL_FRAMEBUFFER, halfFramebuffer_, "postfx.god_rays.half_framebuffer");
  glCreateBuffers(1, &uniformBuffer_);
  glNamedBufferStorage(uniformBuffer_, sizeof(shared::GodRaysBlock), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glkit::label(GL_BUFFER, uniformBuffer_, "postfx.god_rays.block");
  glCreateSamplers(1, &halfSampler_);
  glSamplerParameteri(halfSampler_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glSamplerParameteri(halfSampler_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glSamplerParameteri(halfSampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(halfSampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glkit::label(GL_SAMPLER, halfSampler_, "postfx.sampler.god_rays_half");
  return Result::Ok;
}

void GodRaysPass::release() {
  full_ = glkit::Program();
  half_ = glkit::Program();
  upsample_ = glkit::Program();
  if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
  if (halfFramebuffer_ != 0) glDeleteFramebuffers(1, &halfFramebuffer_);
  if (uniformBuffer_ != 0) glDeleteBuffers(1, &uniformBuffer_);
  if (halfTexture_ != 0) glDeleteTextures(1, &halfTexture_);
  if (halfSampler_ != 0) glDeleteSamplers(1, &halfSampler_);
  framebuffer_ = halfFramebuffer_ = uniformBuffer_ = halfTexture_ = halfSampler_ = 0;
  halfWidth_ = halfHeight_ = 0;
}

void GodRaysPass::ensureHalf(int width, int height) {
  const int w = halfSize(width), h = halfSize(height);
  if (halfTexture_ != 0 && halfWidth_ == w && halfHeight_ == h) return;
  if (halfTexture_ != 0) glDeleteTextures(1, &halfTexture_);
  // RGBA16F rather than R11F_G11F_B10F: alpha carries each texel's distance for the upsample.
  glCreateTextures(GL_TEXTURE_2D, 1, &halfTexture_);
  glTextureStorage2D(halfTexture_, 1, GL_RGBA16F, w, h);
  glkit::label(GL_TEXTURE, halfTexture_, "postfx.god_rays.half");
  glNamedFramebufferTexture(halfFramebuffer_, GL_COLOR_ATTACHMENT0, halfTexture_, 0);
  halfWidth_ = w;
  halfHeight_ = h;
}

Result GodRaysPass::prepare(const FrameDesc& frame, int width, int height,
                            const shared::GodRaysBlock& block, std::string& error) {
  if (frame.godRays.halfResolution) ensureHalf(width, height);
  if (!attachHostTarget(framebuffer_, frame.target.texture, "god-ray", error)) {
    finish();
    return Result::GlError;
  }
  glNamedBufferSubData(uniformBuffer_, 0, sizeof(block), &block);
  return Result::Ok;
}

void GodRaysPass::draw(const FrameDesc& frame, int width, int height) {
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_GODRAYS_BLOCK_BINDING, uniformBuffer_);
  if (!frame.godRays.halfResolution) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
    glUseProgram(full_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return;
  }
  // March at half size, unblended: every texel is written (light and distance).
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, halfFramebuffer_);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(halfWidth_),
                     static_cast<float>(halfHeight_));
  glDisablei(GL_BLEND, 0);
  glUseProgram(half_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Upsample, added into the target.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height));
  glEnablei(GL_BLEND, 0);
  glBindTextureUnit(kHalfUnit, halfTexture_);
  glBindSampler(kHalfUnit, halfSampler_);
  glUseProgram(upsample_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GodRaysPass::finish() {
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace postfx::detail
