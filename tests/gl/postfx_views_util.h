#pragma once
// Shared by the multi-view tests (postfx/views.h): views owned by a test, and the view of a test
// scene.
#include <gtest/gtest.h>

#include <memory>

#include <postfx/views.h>

#include "postfx_scene.h"

namespace postfxtest {

struct ViewDeleter {
  postfx::Context* context;
  void operator()(postfx::View* v) const { postfx::destroyView(*context, v); }
};
using ViewPtr = std::unique_ptr<postfx::View, ViewDeleter>;

inline ViewPtr makeView(postfx::Context& fx) {
  postfx::View* v = nullptr;
  EXPECT_EQ(postfx::createView(fx, v), postfx::Result::Ok) << postfx::lastError(&fx);
  return ViewPtr(v, ViewDeleter{&fx});
}

// The view of `scene`: the G-buffer, target and camera makeFrame gives a frame of it.
inline postfx::ViewDesc viewOf(postfx::View* view, const Scene& scene,
                               const glm::dvec3& offset = {}) {
  const postfx::FrameDesc f = makeFrame(scene, 0, 1, offset);
  postfx::ViewDesc v;
  v.view = view;
  v.depth = f.depth;
  v.normal = f.normal;
  v.albedo = f.albedo;
  v.target = f.target;
  v.camera = f.camera;
  return v;
}

}  // namespace postfxtest
