#include "core/draw_state_guard.h"

#include <algorithm>

#include "core/gl_state_guard.h"

namespace postfx::detail {
namespace {

// Every one is off for the plugin's draws: none of its passes multisamples, smooths, offsets,
// restarts, culls, clips, dithers or tests stencil; a pass that needs depth testing, blending
// or program point size turns it on itself.
constexpr GLenum kCaps[DrawStateGuard::kCapCount] = {GL_COLOR_LOGIC_OP,
                                                     GL_MULTISAMPLE,
                                                     GL_SAMPLE_ALPHA_TO_COVERAGE,
                                                     GL_SAMPLE_ALPHA_TO_ONE,
                                                     GL_SAMPLE_COVERAGE,
                                                     GL_SAMPLE_MASK,
                                                     GL_SAMPLE_SHADING,
                                                     GL_RASTERIZER_DISCARD,
                                                     GL_POLYGON_OFFSET_FILL,
                                                     GL_POLYGON_OFFSET_LINE,
                                                     GL_POLYGON_OFFSET_POINT,
                                                     GL_DEPTH_CLAMP,
                                                     GL_FRAMEBUFFER_SRGB,
                                                     GL_PRIMITIVE_RESTART,
                                                     GL_PRIMITIVE_RESTART_FIXED_INDEX,
                                                     GL_DITHER,
                                                     GL_STENCIL_TEST,
                                                     GL_DEPTH_TEST,
                                                     GL_CULL_FACE,
                                                     GL_LINE_SMOOTH,
                                                     GL_POLYGON_SMOOTH,
                                                     GL_PROGRAM_POINT_SIZE};

int boundedLimit(GLenum pname, int most) {
  GLint value = 0;
  glGetIntegerv(pname, &value);
  return std::clamp(static_cast<int>(value), 0, most);
}

}  // namespace

Result checkHostDrawState(std::string& error) {
  GLint feedback = 0, active = GL_FALSE, paused = GL_FALSE;
  glGetIntegerv(GL_TRANSFORM_FEEDBACK_BINDING, &feedback);
  glGetTransformFeedbackiv(static_cast<GLuint>(feedback), GL_TRANSFORM_FEEDBACK_ACTIVE, &active);
  glGetTransformFeedbackiv(static_cast<GLuint>(feedback), GL_TRANSFORM_FEEDBACK_PAUSED, &paused);
  if (active == GL_TRUE && paused != GL_TRUE) {
    error =
        "GL state: transform feedback is active; pause or end it before dispatch() (the "
        "plugin's draws cannot run inside it)";
    return Result::InvalidArgument;
  }
  return Result::Ok;
}

DrawStateGuard::DrawStateGuard() {
  for (int i = 0; i < kCapCount; ++i) {
    caps_[i] = glIsEnabled(kCaps[i]);
    glDisable(kCaps[i]);
  }
  clipDistanceCount_ = boundedLimit(GL_MAX_CLIP_DISTANCES, kMaxClipDistances);
  for (int i = 0; i < clipDistanceCount_; ++i) {
    const GLenum cap = static_cast<GLenum>(GL_CLIP_DISTANCE0 + i);
    clipDistance_[i] = glIsEnabled(cap);
    glDisable(cap);
  }
  drawBufferCount_ = boundedLimit(GL_MAX_DRAW_BUFFERS, kMaxDrawBuffers);
  for (int i = 0; i < drawBufferCount_; ++i) {
    const GLuint n = static_cast<GLuint>(i);
    DrawBuffer& b = drawBuffers_[i];
    b.blend = glIsEnabledi(GL_BLEND, n);
    glGetIntegeri_v(GL_BLEND_SRC_RGB, n, &b.srcRgb);
    glGetIntegeri_v(GL_BLEND_DST_RGB, n, &b.dstRgb);
    glGetIntegeri_v(GL_BLEND_SRC_ALPHA, n, &b.srcAlpha);
    glGetIntegeri_v(GL_BLEND_DST_ALPHA, n, &b.dstAlpha);
    glGetIntegeri_v(GL_BLEND_EQUATION_RGB, n, &b.equationRgb);
    glGetIntegeri_v(GL_BLEND_EQUATION_ALPHA, n, &b.equationAlpha);
    glGetBooleani_v(GL_COLOR_WRITEMASK, n, b.colorMask);
    glDisablei(GL_BLEND, n);
    glBlendFuncSeparatei(n, GL_ONE, GL_ZERO, GL_ONE, GL_ZERO);
    glBlendEquationSeparatei(n, GL_FUNC_ADD, GL_FUNC_ADD);
    glColorMaski(n, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  }
  viewportCount_ = boundedLimit(GL_MAX_VIEWPORTS, kMaxViewports);
  for (int i = 0; i < viewportCount_; ++i) {
    scissor_[i] = glIsEnabledi(GL_SCISSOR_TEST, static_cast<GLuint>(i));
    glDisablei(GL_SCISSOR_TEST, static_cast<GLuint>(i));
  }
  glGetIntegerv(GL_LOGIC_OP_MODE, &logicOp_);
  glLogicOp(GL_COPY);
  glGetIntegerv(GL_PROVOKING_VERTEX, &provokingVertex_);
  glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
  glGetIntegerv(GL_POLYGON_MODE, polygonMode_);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  glGetFloatv(GL_BLEND_COLOR, blendColor_);
  glBlendColor(0.0f, 0.0f, 0.0f, 0.0f);
  glGetFloatv(GL_SAMPLE_COVERAGE_VALUE, &sampleCoverage_);
  glGetBooleanv(GL_SAMPLE_COVERAGE_INVERT, &sampleCoverageInvert_);
  glSampleCoverage(1.0f, GL_FALSE);
  glGetIntegeri_v(GL_SAMPLE_MASK_VALUE, 0, &sampleMask_);
  glSampleMaski(0, ~0u);
  glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepthMode_);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glGetIntegerv(GL_POINT_SPRITE_COORD_ORIGIN, &pointSpriteOrigin_);
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
  glDepthMask(GL_FALSE);
  glDepthFunc(GL_LESS);
}

DrawStateGuard::~DrawStateGuard() {
  for (int i = 0; i < kCapCount; ++i) restoreEnabled(kCaps[i], caps_[i]);
  for (int i = 0; i < clipDistanceCount_; ++i)
    restoreEnabled(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i), clipDistance_[i]);
  for (int i = 0; i < drawBufferCount_; ++i) {
    const GLuint n = static_cast<GLuint>(i);
    const DrawBuffer& b = drawBuffers_[i];
    restoreEnabledi(GL_BLEND, n, b.blend);
    glBlendFuncSeparatei(n, static_cast<GLenum>(b.srcRgb), static_cast<GLenum>(b.dstRgb),
                         static_cast<GLenum>(b.srcAlpha), static_cast<GLenum>(b.dstAlpha));
    glBlendEquationSeparatei(n, static_cast<GLenum>(b.equationRgb),
                             static_cast<GLenum>(b.equationAlpha));
    glColorMaski(n, b.colorMask[0], b.colorMask[1], b.colorMask[2], b.colorMask[3]);
  }
  for (int i = 0; i < viewportCount_; ++i)
    restoreEnabledi(GL_SCISSOR_TEST, static_cast<GLuint>(i), scissor_[i]);
  glLogicOp(static_cast<GLenum>(logicOp_));
  glProvokingVertex(static_cast<GLenum>(provokingVertex_));
  // Core profiles keep one mode for both faces.
  glPolygonMode(GL_FRONT_AND_BACK, static_cast<GLenum>(polygonMode_[0]));
  glBlendColor(blendColor_[0], blendColor_[1], blendColor_[2], blendColor_[3]);
  glSampleCoverage(sampleCoverage_, sampleCoverageInvert_);
  glSampleMaski(0, static_cast<GLbitfield>(sampleMask_));
  glClipControl(static_cast<GLenum>(clipOrigin_), static_cast<GLenum>(clipDepthMode_));
  glPointParameteri(GL_POINT_SPRITE_COORD_ORIGIN, pointSpriteOrigin_);
  glDepthMask(depthMask_);
  glDepthFunc(static_cast<GLenum>(depthFunc_));
}

}  // namespace postfx::detail
