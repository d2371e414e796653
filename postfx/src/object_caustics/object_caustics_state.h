#pragma once
// The GL state the object-caustics pass changes beyond what GlStateGuard saves (it rasterizes
// meshes with depth testing and points, which the full-screen passes never do): saved on
// construction, restored on destruction. Use inside a GlStateGuard.
#include <epoxy/gl.h>

namespace postfx::detail {

class ObjectCausticsStateGuard {
 public:
  ObjectCausticsStateGuard();
  ~ObjectCausticsStateGuard();
  ObjectCausticsStateGuard(const ObjectCausticsStateGuard&) = delete;
  ObjectCausticsStateGuard& operator=(const ObjectCausticsStateGuard&) = delete;

 private:
  GLboolean depthTest_ = GL_FALSE, depthMask_ = GL_TRUE, depthClamp_ = GL_FALSE;
  GLint depthFunc_ = GL_LESS;
  GLdouble depthRange_[2] = {0.0, 1.0};
  GLint clipOrigin_ = GL_LOWER_LEFT, clipDepthMode_ = GL_NEGATIVE_ONE_TO_ONE;
  GLboolean primitiveRestart_ = GL_FALSE, primitiveRestartFixed_ = GL_FALSE;
  GLboolean programPointSize_ = GL_FALSE, polygonOffsetFill_ = GL_FALSE;
  GLboolean stencilTest_ = GL_FALSE;
  GLfloat lineWidth_ = 1.0f;  // the volume caustics' lines
};

}  // namespace postfx::detail
