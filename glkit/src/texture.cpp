#include <glkit/program.h>
#include <glkit/texture.h>

namespace glkit {

Texture createTexture2D(GLenum format, int width, int height, GLenum filter,
                        std::string_view name) {
  GLuint texture = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &texture);
  glTextureStorage2D(texture, 1, format, width, height);
  glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, GLint(filter));
  glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, GLint(filter));
  glTextureParameteri(texture, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  label(GL_TEXTURE, texture, name);
  return Texture(texture);
}

Sampler createSampler(GLenum minFilter, GLenum magFilter, GLenum wrap, std::string_view name) {
  GLuint sampler = 0;
  glCreateSamplers(1, &sampler);
  glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GLint(minFilter));
  glSamplerParameteri(sampler, GL_TEXTURE_MAG_FILTER, GLint(magFilter));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_S, GLint(wrap));
  glSamplerParameteri(sampler, GL_TEXTURE_WRAP_T, GLint(wrap));
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_NONE);
  label(GL_SAMPLER, sampler, name);
  return Sampler(sampler);
}

}  // namespace glkit
