#include "gl_fixture.h"

#include <cstdlib>

namespace testsupport {

glcontext::HeadlessContext& glContext() {
  static std::unique_ptr<glcontext::HeadlessContext> context = [] {
    std::string error;
    auto created = glcontext::HeadlessContext::create(/*debug=*/true, error);
    if (!created) {
      ADD_FAILURE() << "no headless GL context: " << error;
      std::abort();  // every GL test needs it; there is nothing sensible to continue with
    }
    return created;
  }();
  return *context;
}

void GlTest::SetUp() {
  glContext().makeCurrent();
  glContext().debugLog().take();
  while (glGetError() != GL_NO_ERROR) {
  }
}

void GlTest::TearDown() {
  expectNoGlErrors("end of test");
}

void GlTest::expectNoGlErrors(const char* where) {
  for (const auto& message : glContext().debugLog().take()) {
    EXPECT_NE(message.type, static_cast<GLenum>(GL_DEBUG_TYPE_ERROR))
        << where << ": " << glcontext::debugMessageString(message);
  }
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << where;
}

}  // namespace testsupport
