#include "gl_state_guard.h"

#include "shader_interface.h"

namespace postfx::water::detail {

static_assert(WATER_IMAGE_UNIT_COUNT == 3, "GlStateGuard saves exactly the units update() binds");

GlStateGuard::GlStateGuard() {
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  for (GLuint unit = 0; unit < images_.size(); ++unit) {
    ImageUnit& image = images_[unit];
    glGetIntegeri_v(GL_IMAGE_BINDING_NAME, unit, &image.name);
    glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, unit, &image.level);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, unit, &image.layered);
    glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, unit, &image.layer);
    glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, unit, &image.access);
    glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, unit, &image.format);
  }
  // glBindBufferBase also replaces the generic binding, so both are saved.
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &storageGeneric_);
  storage_ = glkit::IndexedBufferBinding::save(GL_SHADER_STORAGE_BUFFER, WATER_SPECTRUM_BINDING);
}

GlStateGuard::~GlStateGuard() {
  glUseProgram(static_cast<GLuint>(program_));
  for (GLuint unit = 0; unit < images_.size(); ++unit) {
    const ImageUnit& image = images_[unit];
    glBindImageTexture(unit, static_cast<GLuint>(image.name), image.level,
                       image.layered ? GL_TRUE : GL_FALSE, image.layer,
                       static_cast<GLenum>(image.access), static_cast<GLenum>(image.format));
  }
  storage_.restore();
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(storageGeneric_));
}

}  // namespace postfx::water::detail
