#pragma once
// Saves, on construction, every piece of GL state the plugin's passes may change, and restores
// it on destruction: the host's frame must not notice that dispatch() ran. The list is the
// union of what CausticsPass, GodRaysPass and GpuTimers touch; extend both together.
#include <epoxy/gl.h>

#include <array>

#include <glkit/buffer_binding.h>

namespace postfx::detail {

// glEnable / glDisable a capability back to a saved glIsEnabled value.
void restoreEnabled(GLenum cap, GLboolean on);
// The indexed form (per draw buffer or viewport) of restoreEnabled.
void restoreEnabledi(GLenum cap, GLuint index, GLboolean on);

class GlStateGuard {
 public:
  // Texture units whose 2D / 2D-array / buffer bindings and sampler the passes rebind:
  // [0, unitCount).
  static constexpr int kUnitCount = 7;
  // Draw buffers whose blend / colour-mask state the passes set: [0, kDrawBufferCount).
  static constexpr int kDrawBufferCount = 2;
  static constexpr int kMaxClipDistances = 8;

  GlStateGuard();
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  struct BlendState {
    GLboolean enabled;
    GLint srcRgb, dstRgb, srcAlpha, dstAlpha, equationRgb, equationAlpha;
    GLboolean colorMask[4];
  };
  struct UnitState {
    GLint texture2d, texture2dArray, textureBuffer, sampler;
  };

  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
  GLfloat viewport_[4] = {};
  GLboolean scissor0_ = GL_FALSE;
  std::array<BlendState, kDrawBufferCount> blend_{};
  GLboolean cullFace_ = GL_FALSE, rasterizerDiscard_ = GL_FALSE, programPointSize_ = GL_FALSE;
  GLint polygonMode_[2] = {GL_FILL, GL_FILL};
  int clipDistanceCount_ = 0;
  std::array<GLboolean, kMaxClipDistances> clipDistance_{};
  GLint program_ = 0, vertexArray_ = 0, activeTexture_ = GL_TEXTURE0;
  std::array<UnitState, kUnitCount> units_{};
  // Indexed uniform-buffer bindings the passes use: the caustics block and the god-ray block.
  static constexpr int kUniformBindings = 2;
  GLint uniformBuffer_ = 0;
  std::array<glkit::IndexedBufferBinding, kUniformBindings> uniformIndexed_{};
  GLint queryBuffer_ = 0;
  // The irradiance pass's clamp count (Feature::PhysicalCaustics): SSBO binding 0.
  GLint storageBuffer_ = 0;
  glkit::IndexedBufferBinding storageIndexed_{};
};

}  // namespace postfx::detail
