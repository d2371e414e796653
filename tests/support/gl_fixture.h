#pragma once
// Headless GL test fixture: one EGL context for the whole test binary; every test fails when
// the driver reported a GL error (KHR_debug) or glGetError() is set at the end of the test.
#include <gtest/gtest.h>

#include <glcontext/context.h>

namespace testsupport {

glcontext::HeadlessContext& glContext();

class GlTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  // Fails the current test with every GL error message logged since the last check.
  void expectNoGlErrors(const char* where);
};

}  // namespace testsupport
