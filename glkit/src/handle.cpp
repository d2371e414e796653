#include <glkit/handle.h>
#include <glkit/program.h>

namespace glkit {

void deleteProgram(GLuint name) {
  glDeleteProgram(name);
}
void deleteSync(GLsync sync) {
  glDeleteSync(sync);
}

Texture createTexture(GLenum target, std::string_view name) {
  GLuint texture = 0;
  glCreateTextures(target, 1, &texture);
  label(GL_TEXTURE, texture, name);
  return Texture(texture);
}

Framebuffer createFramebuffer(std::string_view name) {
  GLuint framebuffer = 0;
  glCreateFramebuffers(1, &framebuffer);
  label(GL_FRAMEBUFFER, framebuffer, name);
  return Framebuffer(framebuffer);
}

VertexArray createVertexArray(std::string_view name) {
  GLuint vertexArray = 0;
  glCreateVertexArrays(1, &vertexArray);
  label(GL_VERTEX_ARRAY, vertexArray, name);
  return VertexArray(vertexArray);
}

Buffer createBuffer(GLsizeiptr bytes, const void* data, GLbitfield flags, std::string_view name) {
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, bytes, data, flags);
  label(GL_BUFFER, buffer, name);
  return Buffer(buffer);
}

Query createQuery(GLenum target) {
  GLuint query = 0;
  glCreateQueries(target, 1, &query);
  return Query(query);
}

Query genQuery() {
  GLuint query = 0;
  glGenQueries(1, &query);
  return Query(query);
}

}  // namespace glkit
