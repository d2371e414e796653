#pragma once
// Saves, on construction, every binding the plugin's passes may change (framebuffers, viewport,
// program, vertex array, texture units, samplers, buffers), and restores it on destruction: the
// host's frame must not notice that dispatch() ran. The list is the union of what the passes
// and GpuTimers bind; extend both together. Fixed-function draw state (blend, masks, enables,
// polygon mode, clip distances, scissor) is DrawStateGuard's, constructed inside this one.
#include <epoxy/gl.h>

#include <array>

#include <glkit/buffer_binding.h>

#include "core/shared_math.h"

namespace postfx::detail {

// glEnable / glDisable a capability back to a saved glIsEnabled value.
void restoreEnabled(GLenum cap, GLboolean on);
// The indexed form (per draw buffer or viewport) of restoreEnabled.
void restoreEnabledi(GLenum cap, GLuint index, GLboolean on);

class GlStateGuard {
 public:
  // Texture units the passes rebind. Every target's binding on each is saved, not only the
  // targets the plugin uses: glBindTextureUnit(unit, 0) unbinds all of a unit's targets, so a
  // host's cube map or 3D texture on the unit would be lost.
  static constexpr int kUnitCount = POSTFX_UNIT_COUNT;
  static constexpr int kTargetCount = 11;

  GlStateGuard();
  ~GlStateGuard();
  GlStateGuard(const GlStateGuard&) = delete;
  GlStateGuard& operator=(const GlStateGuard&) = delete;

 private:
  struct UnitState {
    std::array<GLint, kTargetCount> textures;
    GLint sampler;
  };

  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
  GLfloat viewport_[4] = {};
  GLint program_ = 0, vertexArray_ = 0, activeTexture_ = GL_TEXTURE0;
  std::array<UnitState, kUnitCount> units_{};
  // Indexed uniform-buffer bindings the passes use: the caustics, god-ray and local water blocks.
  static constexpr int kUniformBindings = 3;
  GLint uniformBuffer_ = 0;
  std::array<glkit::IndexedBufferBinding, kUniformBindings> uniformIndexed_{};
  GLint queryBuffer_ = 0;
  // SSBO bindings 0 (the irradiance pass's clamp count, the tile irradiance's accumulators), 1
  // and 2 (the tile irradiance's spread: its blur buffer and slope statistics), 3 (the counting
  // shaders' counters, testing::CountShaderWork).
  GLint storageBuffer_ = 0;
  static constexpr int kStorageBindings = 4;
  std::array<glkit::IndexedBufferBinding, kStorageBindings> storageIndexed_{};
  // The tile irradiance's resolve writes through image unit 0.
  struct ImageUnitState {
    GLint texture = 0, level = 0, layered = 0, layer = 0, access = GL_READ_ONLY, format = GL_R8;
  } image_{};
};

}  // namespace postfx::detail
