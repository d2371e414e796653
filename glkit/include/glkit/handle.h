#pragma once
// GL object names owned by C++ objects: deleted when the owner goes out of scope, movable, not
// copyable, so a pass's members free themselves in its destructor and no pass writes a release
// function. Deleting needs the owning GL context current, as every GL call does: an owner is
// destroyed only where its creator already guaranteed that (postfx::destroy checks it and
// otherwise leaks the whole Context, to die with the GL context).
#include <epoxy/gl.h>

#include <string_view>

namespace glkit {

// glDelete* of arrays (glDeleteTextures, ...) applied to one name.
template <auto& glDeleteNames>
void deleteName(GLuint name) {
  glDeleteNames(1, &name);
}
void deleteProgram(GLuint name);
void deleteSync(GLsync sync);

// One owned name; Name{} (0, or a null sync) owns nothing.
template <typename Name, void (*Delete)(Name)>
class Handle {
 public:
  Handle() = default;
  explicit Handle(Name name) : name_(name) {}
  Handle(Handle&& other) noexcept : name_(other.release()) {}
  Handle& operator=(Handle&& other) noexcept {
    if (this != &other) reset(other.release());
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  ~Handle() { reset(); }

  Name id() const { return name_; }
  explicit operator bool() const { return name_ != Name{}; }
  // Gives up ownership: the caller deletes the name.
  Name release() {
    const Name name = name_;
    name_ = Name{};
    return name;
  }
  // Deletes what it owned (if anything) and owns `name` instead.
  void reset(Name name = Name{}) {
    if (name_ != Name{}) Delete(name_);
    name_ = name;
  }

 private:
  Name name_{};
};

using Texture = Handle<GLuint, deleteName<glDeleteTextures>>;
using Framebuffer = Handle<GLuint, deleteName<glDeleteFramebuffers>>;
using Buffer = Handle<GLuint, deleteName<glDeleteBuffers>>;
using Sampler = Handle<GLuint, deleteName<glDeleteSamplers>>;
using Query = Handle<GLuint, deleteName<glDeleteQueries>>;
using VertexArray = Handle<GLuint, deleteName<glDeleteVertexArrays>>;
using Fence = Handle<GLsync, deleteSync>;

// DSA creation (binds nothing), each labelled for debuggers (an empty label: none).
Texture createTexture(GLenum target, std::string_view label);
Framebuffer createFramebuffer(std::string_view label);
VertexArray createVertexArray(std::string_view label);
// Immutable storage of `bytes` (glNamedBufferStorage), `data` may be null.
Buffer createBuffer(GLsizeiptr bytes, const void* data, GLbitfield flags, std::string_view label);
Query createQuery(GLenum target);
// A query name whose object (and target) glBeginQuery makes: for targets some drivers
// glCreateQueries refuses (Mesa 22's, the pipeline statistics of ARB_pipeline_statistics_query).
Query genQuery();

}  // namespace glkit
