#include "object_caustics/object_caustics_state.h"

#include "core/gl_state_guard.h"

namespace postfx::detail {
ObjectCausticsStateGuard::ObjectCausticsStateGuard() {
  depthTest_ = glIsEnabled(GL_DEPTH_TEST);
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask_);
  depthClamp_ = glIsEnabled(GL_DEPTH_CLAMP);
  glGetIntegerv(GL_DEPTH_FUNC, &depthFunc_);
  glGetDoublei_v(GL_DEPTH_RANGE, 0, depthRange_);
  glGetIntegerv(GL_CLIP_ORIGIN, &clipOrigin_);
  glGetIntegerv(GL_CLIP_DEPTH_MODE, &clipDepthMode_);
  primitiveRestart_ = glIsEnabled(GL_PRIMITIVE_RESTART);
  primitiveRestartFixed_ = glIsEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX);
  programPointSize_ = glIsEnabled(GL_PROGRAM_POINT_SIZE);
  polygonOffsetFill_ = glIsEnabled(GL_POLYGON_OFFSET_FILL);
  stencilTest_ = glIsEnabled(GL_STENCIL_TEST);
  glGetFloatv(GL_LINE_WIDTH, &lineWidth_);
}

ObjectCausticsStateGuard::~ObjectCausticsStateGuard() {
  restoreEnabled(GL_DEPTH_TEST, depthTest_);
  glDepthMask(depthMask_);
  restoreEnabled(GL_DEPTH_CLAMP, depthClamp_);
  glDepthFunc(static_cast<GLenum>(depthFunc_));
  glDepthRangeIndexed(0, depthRange_[0], depthRange_[1]);
  glClipControl(static_cast<GLenum>(clipOrigin_), static_cast<GLenum>(clipDepthMode_));
  restoreEnabled(GL_PRIMITIVE_RESTART, primitiveRestart_);
  restoreEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX, primitiveRestartFixed_);
  restoreEnabled(GL_PROGRAM_POINT_SIZE, programPointSize_);
  restoreEnabled(GL_POLYGON_OFFSET_FILL, polygonOffsetFill_);
  restoreEnabled(GL_STENCIL_TEST, stencilTest_);
  glLineWidth(lineWidth_);
}

}  // namespace postfx::detail
