#pragma once
// The fixed-function state that changes what a draw writes, whatever the shader computes: saved
// on construction and set to one neutral baseline for the plugin's own draws (the passes then
// turn on only what they need: additive blending, depth testing for the caster maps), restored
// on destruction. Without it a host that left, say, GL_COLOR_LOGIC_OP enabled got a different
// image (a logic op replaces blending, even on float targets). Bindings live in GlStateGuard;
// this guard is constructed inside it. The one place the plugin saves draw state.
#include <epoxy/gl.h>

#include <array>
#include <string>

#include <postfx/result.h>

namespace postfx::detail {

// Draws are impossible or meaningless under an active (unpaused) transform feedback: the
// plugin's programs capture nothing and GL refuses glUseProgram then. Checked before any state
// is touched; conditional rendering cannot be queried in GL 4.5, see postfx.h.
Result checkHostDrawState(std::string& error);

class DrawStateGuard {
 public:
  // Capabilities enabled or disabled as a whole (clip distances and indexed ones apart).
  static constexpr int kCapCount = 22;
  static constexpr int kMaxClipDistances = 8;
  static constexpr int kMaxDrawBuffers = 8;
  static constexpr int kMaxViewports = 16;

  DrawStateGuard();
  ~DrawStateGuard();
  DrawStateGuard(const DrawStateGuard&) = delete;
  DrawStateGuard& operator=(const DrawStateGuard&) = delete;

 private:
  struct DrawBuffer {
    GLboolean blend;
    GLint srcRgb, dstRgb, srcAlpha, dstAlpha, equationRgb, equationAlpha;
    GLboolean colorMask[4];
  };

  std::array<GLboolean, kCapCount> caps_{};
  int clipDistanceCount_ = 0, drawBufferCount_ = 0, viewportCount_ = 0;
  std::array<GLboolean, kMaxClipDistances> clipDistance_{};
  std::array<DrawBuffer, kMaxDrawBuffers> drawBuffers_{};
  std::array<GLboolean, kMaxViewports> scissor_{};
  GLint logicOp_ = GL_COPY, provokingVertex_ = GL_LAST_VERTEX_CONVENTION;
  GLint polygonMode_[2] = {GL_FILL, GL_FILL};
  GLfloat blendColor_[4] = {};
  GLfloat sampleCoverage_ = 1.0f;
  GLboolean sampleCoverageInvert_ = GL_FALSE;
  GLint sampleMask_ = -1;
  GLint clipOrigin_ = GL_LOWER_LEFT, clipDepthMode_ = GL_NEGATIVE_ONE_TO_ONE;
  GLint pointSpriteOrigin_ = GL_UPPER_LEFT;
  GLboolean depthMask_ = GL_TRUE;
  GLint depthFunc_ = GL_LESS;
};

}  // namespace postfx::detail
