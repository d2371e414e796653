#include "gl_state_guard.h"

#include <algorithm>

#include "shared_math.h"

static_assert(POSTFX_CAUSTICS_BLOCK_BINDING < 2 && POSTFX_GODRAYS_BLOCK_BINDING < 2,
              "GlStateGuard saves uniform-buffer bindings 0 and 1 only");

namespace postfx::detail {

GlStateGuard::GlStateGuard() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
  glGetFloati_v(GL_VIEWPORT, 0, viewport_);
  scissor0_ = glIsEnabledi(GL_SCISSOR_TEST, 0);
  for (GLuint i = 0; i < kDrawBufferCount; ++i) {
    BlendState& b = blend_[i];
    b.enabled = glIsEnabledi(GL_BLEND, i);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, i, &b.srcRgb);
    glGetIntegeri_v(GL_BLEND_DST_RGB, i, &b.dstRgb);
    glGetIntegeri_v(GL_BLEND_SRC_ALPHA, i, &b.srcAlpha);
    glGetIntegeri_v(GL_BLEND_DST_ALPHA, i, &b.dstAlpha);
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, i, &b.equationRgb);
    glGetIntegeri_v(GL_BLEND_EQUATION_ALPHA, i, &b.equationAlpha);
    glGetBooleani_v(GL_COLOR_WRITEMASK, i, b.colorMask);
  }
  cullFace_ = glIsEnabled(GL_CULL_FACE);
  rasterizerDiscard_ = glIsEnabled(GL_RASTERIZER_DISCARD);
  programPointSize_ = glIsEnabled(GL_PROGRAM_POINT_SIZE);
  glGetIntegerv(GL_POLYGON_MODE, polygonMode_);
  GLint maxClip = 0;
  glGetIntegerv(GL_MAX_CLIP_DISTANCES, &maxClip);
  clipDistanceCount_ = std::min(static_cast<int>(maxClip), kMaxClipDistances);
  for (int i = 0; i < clipDistanceCount_; ++i)
    clipDistance_[i] = glIsEnabled(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i));
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
  // Per-unit bindings can only be queried through the active unit; it is restored below.
  for (int unit = 0; unit < kUnitCount; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &units_[unit].texture2d);
    glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &units_[unit].texture2dArray);
    glGetIntegerv(GL_TEXTURE_BINDING_BUFFER, &units_[unit].textureBuffer);
    glGetIntegerv(GL_SAMPLER_BINDING, &units_[unit].sampler);
  }
  glActiveTexture(static_cast<GLenum>(activeTexture_));
  glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniformBuffer_);
  for (GLuint i = 0; i < GLuint(kUniformBindings); ++i) {
    uniformIndexed_[i] = glkit::IndexedBufferBinding::save(GL_UNIFORM_BUFFER, i);
  }
  glGetIntegerv(GL_QUERY_BUFFER_BINDING, &queryBuffer_);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storageBuffer_);
  storageIndexed_ = glkit::IndexedBufferBinding::save(GL_SHADER_STORAGE_BUFFER, 0);
}

void restoreEnabled(GLenum cap, GLboolean on) {
  if (on) {
    glEnable(cap);
  } else {
    glDisable(cap);
  }
}

void restoreEnabledi(GLenum cap, GLuint index, GLboolean on) {
  if (on) {
    glEnablei(cap, index);
  } else {
    glDisablei(cap, index);
  }
}

GlStateGuard::~GlStateGuard() {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
  glViewportIndexedfv(0, viewport_);
  restoreEnabledi(GL_SCISSOR_TEST, 0, scissor0_);
  for (GLuint i = 0; i < kDrawBufferCount; ++i) {
    const BlendState& b = blend_[i];
    restoreEnabledi(GL_BLEND, i, b.enabled);
    glBlendFuncSeparatei(i, static_cast<GLenum>(b.srcRgb), static_cast<GLenum>(b.dstRgb),
                         static_cast<GLenum>(b.srcAlpha), static_cast<GLenum>(b.dstAlpha));
    glBlendEquationSeparatei(i, static_cast<GLenum>(b.equationRgb),
                             static_cast<GLenum>(b.equationAlpha));
    glColorMaski(i, b.colorMask[0], b.colorMask[1], b.colorMask[2], b.colorMask[3]);
  }
  restoreEnabled(GL_CULL_FACE, cullFace_);
  restoreEnabled(GL_RASTERIZER_DISCARD, rasterizerDiscard_);
  restoreEnabled(GL_PROGRAM_POINT_SIZE, programPointSize_);
  // Core profiles keep one mode for both faces.
  glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygonMode_[0]));
  for (int i = 0; i < clipDistanceCount_; ++i)
    restoreEnabled(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i), clipDistance_[i]);
  glUseProgram(static_cast<GLuint>(program_));
  glBindVertexArray(static_cast<GLuint>(vertexArray_));
  for (int unit = 0; unit < kUnitCount; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(units_[unit].texture2d));
    glBindTexture(GL_TEXTURE_2D_ARRAY, static_cast<GLuint>(units_[unit].texture2dArray));
    glBindTexture(GL_TEXTURE_BUFFER, static_cast<GLuint>(units_[unit].textureBuffer));
    glBindSampler(static_cast<GLuint>(unit), static_cast<GLuint>(units_[unit].sampler));
  }
  glActiveTexture(static_cast<GLenum>(activeTexture_));
  // glBindBufferBase/Range also set the generic binding, so the indexed one goes first.
  for (const glkit::IndexedBufferBinding& binding : uniformIndexed_) binding.restore();
  glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniformBuffer_));
  glBindBuffer(GL_QUERY_BUFFER, static_cast<GLuint>(queryBuffer_));
  storageIndexed_.restore();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageBuffer_));
}

}  // namespace postfx::detail
