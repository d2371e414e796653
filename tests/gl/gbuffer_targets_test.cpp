// The render-target helper: formats the plugin expects, resize semantics, bad sizes refused
// with nothing allocated.
#include <gtest/gtest.h>

#include <gbuffer/targets.h>
#include <gl_fixture.h>

namespace {

class GbufferTargets : public testsupport::GlTest {};

GLint internalFormat(GLuint texture) {
  GLint format = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  return format;
}

TEST_F(GbufferTargets, AllocatesTheContractFormats) {
  gbuffer::Targets targets;
  std::string error;
  ASSERT_EQ(targets.resize(64, 36, error), gbuffer::TargetError::None) << error;
  EXPECT_EQ(internalFormat(targets.depth()), GL_DEPTH_COMPONENT32F);
  EXPECT_EQ(internalFormat(targets.normal()), GL_RG16_SNORM);
  EXPECT_EQ(internalFormat(targets.albedo()), GL_SRGB8_ALPHA8);
  EXPECT_EQ(internalFormat(targets.hdr()), GL_RGBA16F);
  GLint width = 0;
  glGetTextureLevelParameteriv(targets.hdr(), 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 64);
  ASSERT_EQ(targets.resize(32, 18, error), gbuffer::TargetError::None) << error;
  glGetTextureLevelParameteriv(targets.hdr(), 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 32);
}

TEST_F(GbufferTargets, BadSizesAreRefusedAndAllocateNothing) {
  gbuffer::Targets targets;
  std::string error;
  EXPECT_EQ(targets.resize(0, 36, error), gbuffer::TargetError::ZeroSize);
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(targets.resize(64, -1, error), gbuffer::TargetError::ZeroSize);
  EXPECT_EQ(targets.resize(1 << 20, 16, error), gbuffer::TargetError::TooLarge);
  EXPECT_EQ(targets.depth(), 0u);
  EXPECT_EQ(targets.width(), 0);
}

}  // namespace
