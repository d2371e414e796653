#pragma once
// A host that left unusual GL state everywhere: bound framebuffers, viewport, scissor, blend,
// depth, stencil, colour mask, program, VAO, active texture and bindings on several units,
// samplers, UBO/SSBO bindings, clip control, pixel store, ... reset() restores GL defaults so
// later tests in the same context start clean.
#include <epoxy/gl.h>

namespace postfxtest {

class HostState {
 public:
  HostState() = default;
  HostState(const HostState&) = delete;
  HostState& operator=(const HostState&) = delete;
  ~HostState() { reset(); }

  void set() {
    reset();
    glCreateTextures(GL_TEXTURE_2D, 1, &color_);
    glTextureStorage2D(color_, 1, GL_RGBA8, 16, 16);
    glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &array_);
    glTextureStorage3D(array_, 1, GL_RGBA8, 4, 4, 2);
    glCreateTextures(GL_TEXTURE_CUBE_MAP, 1, &cube_);
    glTextureStorage2D(cube_, 1, GL_RGBA8, 4, 4);
    glCreateFramebuffers(2, fbos_);
    glNamedFramebufferTexture(fbos_[0], GL_COLOR_ATTACHMENT0, color_, 0);
    glNamedFramebufferTexture(fbos_[1], GL_COLOR_ATTACHMENT0, color_, 0);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbos_[0]);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fbos_[1]);
    glViewport(3, 5, 7, 9);
    glViewportIndexedf(1, 1, 2, 3, 4);
    glEnable(GL_SCISSOR_TEST);
    glScissor(1, 2, 3, 4);
    glEnablei(GL_BLEND, 0);
    glEnablei(GL_BLEND, 1);
    glBlendFuncSeparatei(0, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_DST_ALPHA);
    glBlendFunci(1, GL_DST_COLOR, GL_SRC_COLOR);
    glBlendEquationSeparatei(0, GL_FUNC_REVERSE_SUBTRACT, GL_MAX);
    glBlendEquationi(1, GL_MIN);
    glBlendColor(0.25f, 0.5f, 0.75f, 1.0f);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_FALSE);
    glEnable(GL_STENCIL_TEST);
    glStencilFunc(GL_NOTEQUAL, 3, 0x7f);
    glStencilOp(GL_INCR, GL_DECR, GL_INVERT);
    glStencilMask(0x0f);
    glColorMaski(0, GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
    glColorMaski(1, GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_FRONT_AND_BACK);
    glFrontFace(GL_CW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    glEnable(GL_CLIP_DISTANCE0);
    glEnable(GL_CLIP_DISTANCE3);
    glEnable(GL_FRAMEBUFFER_SRGB);
    glEnable(GL_DEPTH_CLAMP);
    glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
    program_ = glCreateShaderProgramv(GL_FRAGMENT_SHADER, 1, &kFragment);
    glUseProgram(program_);
    glCreateVertexArrays(1, &vao_);
    glBindVertexArray(vao_);
    glCreateBuffers(1, &ubo_);
    glNamedBufferStorage(ubo_, 4096, nullptr, 0);
    glCreateBuffers(1, &ssbo_);
    glNamedBufferStorage(ssbo_, 4096, nullptr, 0);
    glBindBuffer(GL_ARRAY_BUFFER, ssbo_);
    for (GLuint i = 0; i < 4; ++i) {
      glBindBufferRange(GL_UNIFORM_BUFFER, i, ubo_, 256 * (i + 1), 256);
      glBindBufferRange(GL_SHADER_STORAGE_BUFFER, i, ssbo_, 256 * i, 512);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, ssbo_);
    glBindBuffer(GL_QUERY_BUFFER, ubo_);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, ubo_);
    glCreateSamplers(2, samplers_);
    makeEveryTarget();
    // A texture of every target on every unit, the plugin's and the next ones: a pass that
    // unbinds a whole unit (glBindTextureUnit(unit, 0)) or binds past its units shows here.
    for (GLuint unit = 0; unit < kBoundUnits; ++unit) {
      glActiveTexture(GL_TEXTURE0 + unit);
      for (int t = 0; t < kTargets; ++t) glBindTexture(kTargetList[t], targets_[t]);
      glBindSampler(unit, samplers_[unit % 2]);
    }
    for (GLuint image = 0; image < 4; ++image)
      glBindImageTexture(image, color_, 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA8);
    glActiveTexture(GL_TEXTURE6);
    glPixelStorei(GL_PACK_ALIGNMENT, 8);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 2);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 33);
    glPixelStorei(GL_PACK_ROW_LENGTH, 17);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 1);
    active_ = true;
  }

  void reset() {
    if (!active_) return;
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, 1, 1);
    glDisable(GL_SCISSOR_TEST);
    glScissor(0, 0, 1, 1);
    glDisable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ZERO);
    glBlendEquation(GL_FUNC_ADD);
    glBlendColor(0, 0, 0, 0);
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_STENCIL_TEST);
    glStencilFunc(GL_ALWAYS, 0, 0xff);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    glStencilMask(0xff);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDisable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDisable(GL_CLIP_DISTANCE0);
    glDisable(GL_CLIP_DISTANCE3);
    glDisable(GL_FRAMEBUFFER_SRGB);
    glDisable(GL_DEPTH_CLAMP);
    glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
    glUseProgram(0);
    glBindVertexArray(0);
    for (GLuint i = 0; i < 4; ++i) {
      glBindBufferBase(GL_UNIFORM_BUFFER, i, 0);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, i, 0);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_UNIFORM_BUFFER, 0);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glBindBuffer(GL_QUERY_BUFFER, 0);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    for (GLuint unit = 0; unit < kBoundUnits; ++unit) {
      glActiveTexture(GL_TEXTURE0 + unit);
      for (int t = 0; t < kTargets; ++t) glBindTexture(kTargetList[t], 0);
      glBindSampler(unit, 0);
    }
    for (GLuint image = 0; image < 4; ++image)
      glBindImageTexture(image, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
    glActiveTexture(GL_TEXTURE0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    glDeleteFramebuffers(2, fbos_);
    const GLuint textures[] = {color_, array_, cube_};
    glDeleteTextures(3, textures);
    glDeleteTextures(kTargets, targets_);
    glDeleteProgram(program_);
    glDeleteVertexArrays(1, &vao_);
    const GLuint buffers[] = {ubo_, ssbo_};
    glDeleteBuffers(2, buffers);
    glDeleteSamplers(2, samplers_);
    active_ = false;
  }

 public:
  // Units that get a texture of every target (the plugin uses [0, 8)).
  static constexpr GLuint kBoundUnits = 12;
  static constexpr int kTargets = 11;
  static constexpr GLenum kTargetList[kTargets] = {
      GL_TEXTURE_1D,        GL_TEXTURE_1D_ARRAY,       GL_TEXTURE_2D,
      GL_TEXTURE_2D_ARRAY,  GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_2D_MULTISAMPLE_ARRAY,
      GL_TEXTURE_3D,        GL_TEXTURE_CUBE_MAP,       GL_TEXTURE_CUBE_MAP_ARRAY,
      GL_TEXTURE_RECTANGLE, GL_TEXTURE_BUFFER};

 private:
  // One small texture of each target (the buffer texture over the host's SSBO).
  void makeEveryTarget() {
    for (int t = 0; t < kTargets; ++t) {
      const GLenum target = kTargetList[t];
      glCreateTextures(target, 1, &targets_[t]);
      const GLuint id = targets_[t];
      switch (target) {
        case GL_TEXTURE_1D:
          glTextureStorage1D(id, 1, GL_RGBA8, 4);
          break;
        case GL_TEXTURE_1D_ARRAY:
        case GL_TEXTURE_2D:
        case GL_TEXTURE_RECTANGLE:
        case GL_TEXTURE_CUBE_MAP:
          glTextureStorage2D(id, 1, GL_RGBA8, 4, 4);
          break;
        case GL_TEXTURE_2D_MULTISAMPLE:
          glTextureStorage2DMultisample(id, 4, GL_RGBA8, 4, 4, GL_TRUE);
          break;
        case GL_TEXTURE_2D_MULTISAMPLE_ARRAY:
          glTextureStorage3DMultisample(id, 4, GL_RGBA8, 4, 4, 2, GL_TRUE);
          break;
        case GL_TEXTURE_CUBE_MAP_ARRAY:
          glTextureStorage3D(id, 1, GL_RGBA8, 4, 4, 6);
          break;
        case GL_TEXTURE_BUFFER:
          glTextureBuffer(id, GL_RGBA8, ssbo_);
          break;
        default:  // 2D array, 3D
          glTextureStorage3D(id, 1, GL_RGBA8, 4, 4, 2);
      }
    }
  }

  static constexpr const char* kFragment =
      "#version 450 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n";
  bool active_ = false;
  GLuint fbos_[2] = {}, color_ = 0, array_ = 0, cube_ = 0, program_ = 0, vao_ = 0, ubo_ = 0,
         ssbo_ = 0, samplers_[2] = {}, targets_[kTargets] = {};
};

}  // namespace postfxtest
