#include <glkit/program.h>
#include <glkit/texture.h>

namespace glkit {

GLuint createTexture2D(GLenum format, int width, int height, GLenum filter, std::string_view name) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  label(GL_TEXTURE, texture, name);
  return texture;
}

}  // namespace glkit
