// The water module as a drop-in: bad input fails cleanly with nothing allocated, a calm sea is
// flat, odd times are refused without side effects, and update() leaves the host's GL state.
#include <gl_fixture.h>

#include <cstring>
#include <functional>
#include <limits>

#include "water_test_util.h"

namespace {

using testsupport::GlTest;

class WaterRobustness : public GlTest {};

// Names of live GL objects among the first few thousand ids: a failed create must not change it.
int liveObjectCount() {
  int count = 0;
  for (GLuint id = 1; id < 4096; ++id) {
    count += glIsTexture(id) + glIsBuffer(id) + glIsProgram(id) + glIsShader(id);
  }
  return count;
}

TEST_F(WaterRobustness, BadDescriptionsFailWithNothingAllocated) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<std::pair<const char*, std::function<void(postfx::water::OceanDesc&)>>> cases =
      {
          {"zero resolution", [](postfx::water::OceanDesc& d) { d.resolution = 0; }},
          {"non power of two", [](postfx::water::OceanDesc& d) { d.resolution = 96; }},
          {"above 512", [](postfx::water::OceanDesc& d) { d.resolution = 1024; }},
          {"negative wind", [](postfx::water::OceanDesc& d) { d.windSpeed = -3.0; }},
          {"NaN wind", [nan](postfx::water::OceanDesc& d) { d.windSpeed = nan; }},
          {"NaN direction", [nan](postfx::water::OceanDesc& d) { d.windDirection = nan; }},
          {"no cascades", [](postfx::water::OceanDesc& d) { d.cascadeCount = 0; }},
          {"growing tiles", [](postfx::water::OceanDesc& d) { d.tileSize[1] = 300.0; }},
      };
  const int before = liveObjectCount();
  for (const auto& [name, edit] : cases) {
    postfx::water::OceanDesc desc = watertest::smallDesc();
    edit(desc);
    std::unique_ptr<postfx::water::Ocean> ocean;
    std::string error;
    EXPECT_EQ(postfx::water::Ocean::create(desc, ocean, error),
              postfx::water::Result::InvalidArgument)
        << name;
    EXPECT_FALSE(ocean) << name;
    EXPECT_FALSE(error.empty()) << name;
  }
  EXPECT_EQ(liveObjectCount(), before);
}

TEST_F(WaterRobustness, CalmSeaIsFlat) {
  postfx::water::OceanDesc desc = watertest::smallDesc();
  desc.windSpeed = 0.0;
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  ASSERT_EQ(postfx::water::Ocean::create(desc, ocean, error), postfx::water::Result::Ok) << error;
  ASSERT_EQ(ocean->update(12.0), postfx::water::Result::Ok);
  for (const glm::vec4& texel : watertest::readSlope(*ocean)) {
    ASSERT_EQ(texel, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  }
  for (const glm::vec4& texel : watertest::readDisplacement(*ocean)) {
    ASSERT_EQ(texel, glm::vec4(0.0f));
  }
}

TEST_F(WaterRobustness, NonFiniteTimeIsRefusedAndChangesNothing) {
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  ASSERT_EQ(postfx::water::Ocean::create(watertest::smallDesc(), ocean, error),
            postfx::water::Result::Ok);
  ASSERT_EQ(ocean->update(5.0), postfx::water::Result::Ok);
  const auto before = watertest::readSlope(*ocean);
  for (double time :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
        -std::numeric_limits<double>::infinity()}) {
    error.clear();
    EXPECT_EQ(ocean->update(time, error), postfx::water::Result::InvalidArgument);
    EXPECT_FALSE(error.empty());
  }
  const auto after = watertest::readSlope(*ocean);
  EXPECT_EQ(0, std::memcmp(before.data(), after.data(), before.size() * sizeof(glm::vec4)));
}

TEST_F(WaterRobustness, NoNaNAtExtremeButValidSettings) {
  for (double wind : {0.01, 60.0}) {
    postfx::water::OceanDesc desc = watertest::smallDesc();
    desc.windSpeed = wind;
    desc.choppiness = 4.0;
    desc.spreading = 200.0;
    desc.depth = 2.0;
    desc.fetch = 1e7;
    std::unique_ptr<postfx::water::Ocean> ocean;
    std::string error;
    ASSERT_EQ(postfx::water::Ocean::create(desc, ocean, error), postfx::water::Result::Ok) << error;
    for (double time : {-1e9, -3.5, 0.0, 1e-9, 1e7, 1e12}) {
      ASSERT_EQ(ocean->update(time), postfx::water::Result::Ok);
      EXPECT_TRUE(watertest::allFinite(watertest::readSlope(*ocean))) << wind << " " << time;
      EXPECT_TRUE(watertest::allFinite(watertest::readDisplacement(*ocean))) << wind << " " << time;
    }
  }
}

TEST_F(WaterRobustness, SameDescriptionGivesBitIdenticalTextures) {
  std::unique_ptr<postfx::water::Ocean> first, second;
  std::string error;
  ASSERT_EQ(postfx::water::Ocean::create(watertest::smallDesc(), first, error),
            postfx::water::Result::Ok);
  ASSERT_EQ(postfx::water::Ocean::create(watertest::smallDesc(), second, error),
            postfx::water::Result::Ok);
  ASSERT_EQ(first->update(33.0), postfx::water::Result::Ok);
  ASSERT_EQ(second->update(33.0), postfx::water::Result::Ok);
  const auto a = watertest::readSlope(*first), b = watertest::readSlope(*second);
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::vec4)));
}

TEST_F(WaterRobustness, ReportsTheMemoryItHolds) {
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  ASSERT_EQ(postfx::water::Ocean::create(watertest::smallDesc(), ocean, error),
            postfx::water::Result::Ok);
  // 64^2 x 3 cascades: spectrum 20 B, scratch 2 x 16 B, two RGBA16F chains of 8 B x 4/3.
  const size_t texels = 64 * 64 * 3;
  size_t chain = 0;
  for (int side = 64; side >= 1; side /= 2) chain += static_cast<size_t>(side) * side * 3;
  EXPECT_EQ(ocean->gpuBytes(), texels * 20 + texels * 32 + 2 * chain * 8);
}

// update() binds a program, three image units and a storage buffer: all must come back.
TEST_F(WaterRobustness, UpdateRestoresTheHostsGlState) {
  std::unique_ptr<postfx::water::Ocean> ocean;
  std::string error;
  ASSERT_EQ(postfx::water::Ocean::create(watertest::smallDesc(), ocean, error),
            postfx::water::Result::Ok);

  GLuint hostTexture = 0, hostBuffer = 0, otherBuffer = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &hostTexture);
  glTextureStorage3D(hostTexture, 2, GL_R32F, 8, 8, 4);
  glCreateBuffers(1, &hostBuffer);
  glNamedBufferStorage(hostBuffer, 1024, nullptr, 0);
  glCreateBuffers(1, &otherBuffer);
  glNamedBufferStorage(otherBuffer, 256, nullptr, 0);
  const GLuint hostProgram = glCreateProgram();  // never linked: glUseProgram needs a linked one
  GLuint linked = 0;
  {
    const char* source = "#version 450 core\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
    const GLuint shader = glCreateShader(GL_COMPUTE_SHADER);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    linked = hostProgram;
    glAttachShader(linked, shader);
    glLinkProgram(linked);
    glDeleteShader(shader);
  }
  glUseProgram(linked);
  glBindImageTexture(0, hostTexture, 1, GL_FALSE, 2, GL_READ_WRITE, GL_R32F);
  glBindImageTexture(2, hostTexture, 0, GL_TRUE, 0, GL_READ_ONLY, GL_R32F);
  glBindBufferRange(GL_SHADER_STORAGE_BUFFER, 0, hostBuffer, 256, 512);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, otherBuffer);

  ASSERT_EQ(ocean->update(9.0), postfx::water::Result::Ok);

  GLint value = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &value);
  EXPECT_EQ(static_cast<GLuint>(value), linked);
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 0, &value);
  EXPECT_EQ(static_cast<GLuint>(value), hostTexture);
  glGetIntegeri_v(GL_IMAGE_BINDING_LEVEL, 0, &value);
  EXPECT_EQ(value, 1);
  glGetIntegeri_v(GL_IMAGE_BINDING_LAYERED, 0, &value);
  EXPECT_EQ(value, GL_FALSE);
  glGetIntegeri_v(GL_IMAGE_BINDING_LAYER, 0, &value);
  EXPECT_EQ(value, 2);
  glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, 0, &value);
  EXPECT_EQ(value, GL_READ_WRITE);
  glGetIntegeri_v(GL_IMAGE_BINDING_FORMAT, 0, &value);
  EXPECT_EQ(value, GL_R32F);
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 1, &value);
  EXPECT_EQ(value, 0);
  glGetIntegeri_v(GL_IMAGE_BINDING_NAME, 2, &value);
  EXPECT_EQ(static_cast<GLuint>(value), hostTexture);
  glGetIntegeri_v(GL_IMAGE_BINDING_ACCESS, 2, &value);
  EXPECT_EQ(value, GL_READ_ONLY);
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, &value);
  EXPECT_EQ(static_cast<GLuint>(value), hostBuffer);
  GLint64 range = 0;
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_START, 0, &range);
  EXPECT_EQ(range, 256);
  glGetInteger64i_v(GL_SHADER_STORAGE_BUFFER_SIZE, 0, &range);
  EXPECT_EQ(range, 512);
  glGetIntegerv(GL_SHADER_STORAGE_BUFFER_BINDING, &value);
  EXPECT_EQ(static_cast<GLuint>(value), otherBuffer);

  glUseProgram(0);
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
  glBindImageTexture(2, 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R8);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  glDeleteProgram(linked);
  glDeleteBuffers(1, &hostBuffer);
  glDeleteBuffers(1, &otherBuffer);
  glDeleteTextures(1, &hostTexture);
}

}  // namespace
