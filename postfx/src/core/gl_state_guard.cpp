#include "core/gl_state_guard.h"

#include "core/shared_math.h"

static_assert(POSTFX_CAUSTICS_BLOCK_BINDING < 3 && POSTFX_GODRAYS_BLOCK_BINDING < 3 &&
                  POSTFX_LOCAL_WATER_BLOCK_BINDING < 3,
              "GlStateGuard saves uniform-buffer bindings 0-2 only");
static_assert(POSTFX_UNIT_IRRADIANCE < POSTFX_UNIT_COUNT &&
                  POSTFX_UNIT_GODRAYS_REDUCED < POSTFX_UNIT_COUNT &&
                  POSTFX_UNIT_GRID_POINTS < POSTFX_UNIT_COUNT &&
                  POSTFX_UNIT_TILE_IRRADIANCE < POSTFX_UNIT_COUNT &&
                  POSTFX_OBJECT_UNIT_LANDINGS < POSTFX_UNIT_COUNT &&
                  POSTFX_UNIT_LOCAL_WATER < POSTFX_UNIT_COUNT,
              "GlStateGuard saves texture units [0, POSTFX_UNIT_COUNT) only");
static_assert(POSTFX_STORAGE_GRID_POINTS == 0 && POSTFX_STORAGE_CLAMP_COUNT == 0 &&
                  POSTFX_STORAGE_TILE_ACCUMULATORS == 0 && POSTFX_STORAGE_TILE_BLUR == 1 &&
                  POSTFX_STORAGE_TILE_SPREAD == 2 && POSTFX_IMAGE_TILE_IRRADIANCE == 0 &&
                  POSTFX_IMAGE_OBJECT_LANDINGS == 0,
              "GlStateGuard saves shader-storage bindings 0-2 and image unit 0 only");

namespace postfx::detail {
namespace {

struct TargetBinding {
  GLenum target, binding;
};
// Every texture target of GL 4.5 with the query that reads its binding on the active unit.
constexpr TargetBinding kTargets[GlStateGuard::kTargetCount] = {
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE},
    {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY},
    {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER}};

}  // namespace

GlStateGuard::GlStateGuard() {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
  glGetFloati_v(GL_VIEWPORT, 0, viewport_);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
  // Per-unit bindings can only be queried through the active unit; it is restored below.
  for (int unit = 0; unit < kUnitCount; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    for (int t = 0; t < kTargetCount; ++t)
      glGetIntegerv(kTargets[t].binding, &units_[unit].textures[t]);
    glGetIntegerv(GL_SAMPLER_BINDING, &units_[unit].sampler);
  }
  glActiveTexture(static_cast<GLenum>(activeTexture_));
  glGetIntegerv(GL_UNIFORM_BUFFER_BINDING, &uniformBuffer_);
  for (GLuint i = 0; i < GLuint(kUniformBindings); ++i) {
    uniformIndexed_[i] = glkit::IndexedBufferBinding::save(GL_UNIFORM_BUFFER, i);
  }
  glGetIntegerv(GL_QUERY_BUFFER_BINDING, &queryBuffer_);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storageBuffer_);
  for (GLuint i = 0; i < GLuint(kStorageBindings); ++i)
    storageIndexed_[i] = glkit::IndexedBufferBinding::save(GL_SHADER_STORAGE_BUFFER, i);
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &image_.texture);
  glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, 0, &image_.level);
  glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, 0, &image_.layered);
  glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, 0, &image_.layer);
  glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, 0, &image_.access);
  glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, 0, &image_.format);
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
  glUseProgram(static_cast<GLuint>(program_));
  glBindVertexArray(static_cast<GLuint>(vertexArray_));
  for (int unit = 0; unit < kUnitCount; ++unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    for (int t = 0; t < kTargetCount; ++t)
      glBindTexture(kTargets[t].target, static_cast<GLuint>(units_[unit].textures[t]));
    glBindSampler(static_cast<GLuint>(unit), static_cast<GLuint>(units_[unit].sampler));
  }
  glActiveTexture(static_cast<GLenum>(activeTexture_));
  // glBindBufferBase/Range also set the generic binding, so the indexed one goes first.
  for (const glkit::IndexedBufferBinding& binding : uniformIndexed_) binding.restore();
  glBindBuffer(GL_UNIFORM_BUFFER, static_cast<GLuint>(uniformBuffer_));
  glBindBuffer(GL_QUERY_BUFFER, static_cast<GLuint>(queryBuffer_));
  for (const glkit::IndexedBufferBinding& binding : storageIndexed_) binding.restore();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageBuffer_));
  glBindImageTexture(0, static_cast<GLuint>(image_.texture), image_.level,
                     image_.layered ? GL_TRUE : GL_FALSE, image_.layer,
                     static_cast<GLenum>(image_.access), static_cast<GLenum>(image_.format));
}

}  // namespace postfx::detail
