// Validation that cannot be fooled: values that once passed validation and then
// wrote NaN, raised GL errors in the host's context or poisoned the context are refused with a
// message and the target bit-identical, or accepted with finite output; an accepted extreme
// frame leaves no trace in the next ordinary frame.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <vector>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfx::Feature;
using postfx::Result;

const glm::vec4 kMarker(0.125f, 0.25f, 0.5f, 1.0f);

postfxtest::SceneSpec smallSpec() {
  postfxtest::SceneSpec spec;
  spec.width = 64;
  spec.height = 36;
  return spec;
}

bool sameBits(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

int nonFinite(const std::vector<glm::vec4>& image) {
  int count = 0;
  for (const glm::vec4& p : image)
    for (int c = 0; c < 4; ++c) count += std::isfinite(p[c]) ? 0 : 1;
  return count;
}

class PostfxRefusalTest : public testsupport::GlTest {
 protected:
  // Dispatches into a target holding the marker; returns the target afterwards.
  std::vector<glm::vec4> dispatch(postfx::Context& fx, const postfxtest::Scene& scene,
                                  const postfx::FrameDesc& frame, Result& result) {
    scene.clearTarget(kMarker);
    result = postfx::dispatch(fx, frame);
    return postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height);
  }
};

constexpr Feature kEverySeabedPass =
    Feature::Caustics | Feature::GodRays | Feature::Dispersion | postfx::testing::RawCausticOutput;

// Far values whose double -> float conversion after a subtraction gave Inf (then NaN in 11058
// of 16384 target values): refused, naming the field, target untouched.
TEST_F(PostfxRefusalTest, PositionsPastTheWorldExtentAreRefused) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.02);
  auto fx = postfxtest::makeContext(kEverySeabedPass);
  struct Case {
    const char* name;
    const char* mentions;
    std::function<void(postfx::FrameDesc&)> spoil;
  };
  const Case cases[] = {
      {"water level 1e300, no absorption", "water.level",
       [](postfx::FrameDesc& f) {
         f.water.level = 1e300;
         f.water.absorption = glm::vec3(0.0f);
       }},
      {"camera y -1e300, no absorption", "camera.position",
       [](postfx::FrameDesc& f) {
         f.camera.position.y = -1e300;
         f.water.absorption = glm::vec3(0.0f);
       }},
      {"camera x 1e15", "camera.position",
       [](postfx::FrameDesc& f) { f.camera.position.x = 1e15; }},
      {"camera z just past 1e9", "camera.position",
       [](postfx::FrameDesc& f) { f.camera.position.z = -1.000001e9; }},
      {"water origin 1e30", "water.origin", [](postfx::FrameDesc& f) { f.water.origin.x = 1e30; }},
      {"sun whose squared length overflows", "sun.direction",
       [](postfx::FrameDesc& f) { f.sun.direction = glm::dvec3(0.0, 1e300, 0.0); }},
      {"sun 1e7 long", "sun.direction",
       [](postfx::FrameDesc& f) { f.sun.direction = glm::dvec3(0.0, 1e7, 0.0); }},
      {"sun 1e-7 long", "sun.direction",
       [](postfx::FrameDesc& f) { f.sun.direction = glm::dvec3(0.0, 1e-7, 0.0); }},
      {"projection with 1e300 focal length", "camera.projection",
       [](postfx::FrameDesc& f) { f.camera.projection[1][1] = 1e300; }},
      {"projection with a 1e-300 focal length", "camera.projection",
       [](postfx::FrameDesc& f) { f.camera.projection[0][0] = 1e-300; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    c.spoil(frame);
    Result r = Result::Ok;
    const std::vector<glm::vec4> after = dispatch(*fx, scene, frame, r);
    EXPECT_EQ(r, Result::InvalidArgument);
    EXPECT_NE(std::string(postfx::lastError(fx.get())).find(c.mentions), std::string::npos)
        << postfx::lastError(fx.get());
    for (const glm::vec4& v : after) ASSERT_EQ(v, kMarker) << "something was drawn";
    expectNoGlErrors(c.name);
  }
  EXPECT_EQ(postfx::stats(*fx).framesDispatched, 0u) << "refused frames leave the timers alone";

  // At the extent itself every value is finite (the bound is where float still holds them).
  const std::function<void(postfx::FrameDesc&)> edges[] = {
      [](postfx::FrameDesc& f) {
        f.water.level = 1e9;
        f.water.absorption = glm::vec3(0.0f);
      },
      [](postfx::FrameDesc& f) {
        f.camera.position = glm::dvec3(1e9, -1e9, -1e9);
        f.water.level = 1e9;
        f.water.origin = glm::dvec2(-1e9, 1e9);
        f.water.absorption = glm::vec3(0.0f);
      },
      [](postfx::FrameDesc& f) { f.sun.direction = glm::dvec3(0.3e6, 1e6, -0.2e6) * 0.7; },
  };
  for (const auto& edge : edges) {
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    edge(frame);
    Result r = Result::InvalidArgument;
    const std::vector<glm::vec4> after = dispatch(*fx, scene, frame, r);
    EXPECT_EQ(r, Result::Ok) << postfx::lastError(fx.get());
    EXPECT_EQ(nonFinite(after), 0);
    EXPECT_FALSE(sameBits(after, std::vector<glm::vec4>(after.size(), kMarker)))
        << "the frame at the extent drew (the test can tell)";
    const std::vector<float> raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx),
                                                       scene.spec().width, scene.spec().height);
    for (float v : raw) ASSERT_TRUE(std::isfinite(v));
  }
  glDeleteTextures(1, &water);
}

// The shadow matrix about the camera and the projection are finite doubles whose products
// overflow float: the last check over every uniform block refuses them.
TEST_F(PostfxRefusalTest, ConstantsThatOverflowFloatAreRefused) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.02);
  GLuint shadow = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &shadow);
  glTextureStorage2D(shadow, 1, GL_DEPTH_COMPONENT32F, 16, 16);
  auto fx = postfxtest::makeContext(Feature::Caustics | Feature::ShadowMask);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  frame.shadow.depth = {shadow, GL_DEPTH_COMPONENT32F};
  frame.shadow.worldToLightClip = glm::dmat4(1e37);  // finite, but x 1e2 m of camera: > FLT_MAX
  frame.camera.position.x = 100.0;
  Result r = Result::Ok;
  for (const glm::vec4& v : dispatch(*fx, scene, frame, r)) ASSERT_EQ(v, kMarker);
  EXPECT_EQ(r, Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(fx.get())).find("shadow.worldToLightClip"),
            std::string::npos)
      << postfx::lastError(fx.get());
  frame.shadow.worldToLightClip = glm::dmat4(1.0);
  dispatch(*fx, scene, frame, r);
  EXPECT_EQ(r, Result::Ok) << postfx::lastError(fx.get());
  glDeleteTextures(1, &shadow);
  glDeleteTextures(1, &water);
}

// A sun that is not unit is normalised, as the header says: the same image as the unit one.
TEST_F(PostfxRefusalTest, NonUnitSunIsNormalised) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.02);
  auto fx = postfxtest::makeContext(kEverySeabedPass);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  frame.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  Result r = Result::InvalidArgument;
  const std::vector<glm::vec4> unit = dispatch(*fx, scene, frame, r);
  ASSERT_EQ(r, Result::Ok);
  for (double length : {1e-6, 0.5, 3.0, 1e6}) {
    postfx::FrameDesc scaled = frame;
    scaled.sun.direction = frame.sun.direction * length;
    const std::vector<glm::vec4> image = dispatch(*fx, scene, scaled, r);
    EXPECT_EQ(r, Result::Ok) << length;
    double worst = 0.0;
    for (size_t i = 0; i < image.size(); ++i)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, double(std::abs(image[i][c] - unit[i][c])));
    // normalize() of a scaled vector rounds differently in the last bit of double; in float
    // nothing is left of it.
    EXPECT_LT(worst, 1e-6) << "sun length " << length;
  }
  glDeleteTextures(1, &water);
}

// Every kind of texture in every texture slot: refused with the slot named and no GL error in
// the host's context (a buffer texture made validation itself raise GL_INVALID_OPERATION).
TEST_F(PostfxRefusalTest, EveryTextureKindInEverySlotIsRefusedWithoutGlErrors) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.02);
  GLuint buffer = 0;
  glCreateBuffers(1, &buffer);
  glNamedBufferStorage(buffer, 4096, nullptr, 0);
  struct Kind {
    const char* name;
    GLuint texture;
  };
  std::vector<Kind> kinds;
  auto make = [&kinds](const char* name, GLenum target,
                       const std::function<void(GLuint)>& storage) {
    GLuint t = 0;
    glCreateTextures(target, 1, &t);
    storage(t);
    kinds.push_back({name, t});
  };
  make("buffer texture", GL_TEXTURE_BUFFER,
       [buffer](GLuint t) { glTextureBuffer(t, GL_RGBA32F, buffer); });
  make("buffer texture without a buffer", GL_TEXTURE_BUFFER, [](GLuint) {});
  make("1D", GL_TEXTURE_1D, [](GLuint t) { glTextureStorage1D(t, 1, GL_RGBA16F, 64); });
  make("1D array", GL_TEXTURE_1D_ARRAY,
       [](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA16F, 64, 36); });
  make("3D", GL_TEXTURE_3D, [](GLuint t) { glTextureStorage3D(t, 1, GL_RGBA16F, 64, 36, 3); });
  make("cube map", GL_TEXTURE_CUBE_MAP,
       [](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA16F, 36, 36); });
  make("cube map array", GL_TEXTURE_CUBE_MAP_ARRAY,
       [](GLuint t) { glTextureStorage3D(t, 1, GL_RGBA16F, 36, 36, 6); });
  make("rectangle", GL_TEXTURE_RECTANGLE,
       [](GLuint t) { glTextureStorage2D(t, 1, GL_RGBA16F, 64, 36); });
  make("2D multisample", GL_TEXTURE_2D_MULTISAMPLE,
       [](GLuint t) { glTextureStorage2DMultisample(t, 4, GL_RGBA16F, 64, 36, GL_TRUE); });
  make("2D multisample array", GL_TEXTURE_2D_MULTISAMPLE_ARRAY,
       [](GLuint t) { glTextureStorage3DMultisample(t, 4, GL_RGBA16F, 64, 36, 3, GL_TRUE); });
  make("2D without storage", GL_TEXTURE_2D, [](GLuint) {});
  make("2D array in a 2D slot", GL_TEXTURE_2D_ARRAY,
       [](GLuint t) { glTextureStorage3D(t, 1, GL_RGBA16F, 64, 36, 1); });
  expectNoGlErrors("making the textures");

  GLuint shadow = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &shadow);
  glTextureStorage2D(shadow, 1, GL_DEPTH_COMPONENT32F, 16, 16);
  auto fx = postfxtest::makeContext(Feature::Caustics | Feature::GodRays | Feature::ShadowMask);
  const char* slots[] = {"target", "depth", "normal", "albedo", "water.texture", "shadow.depth"};
  int refused = 0;
  for (const Kind& kind : kinds) {
    for (const char* slot : slots) {
      if (std::string(kind.name) == "2D array in a 2D slot" && std::string(slot) == "water.texture")
        continue;  // the water slot takes an array: that one is accepted (not a bad input)
      SCOPED_TRACE(std::string(kind.name) + " as " + slot);
      postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1);
      frame.shadow.depth = {shadow, 0};
      const postfx::TextureRef ref{kind.texture, 0};
      const std::string s = slot;
      if (s == "target") frame.target = ref;
      if (s == "depth") frame.depth = ref;
      if (s == "normal") frame.normal = ref;
      if (s == "albedo") frame.albedo = ref;
      if (s == "water.texture") frame.water.texture = ref;
      if (s == "shadow.depth") frame.shadow.depth = ref;
      Result r = Result::Ok;
      const std::vector<glm::vec4> after = dispatch(*fx, scene, frame, r);
      EXPECT_TRUE(r == Result::UnsupportedFormat || r == Result::MissingTexture)
          << postfx::toString(r);
      EXPECT_NE(std::string(postfx::lastError(fx.get())).find(slot), std::string::npos)
          << postfx::lastError(fx.get());
      for (const glm::vec4& v : after) ASSERT_EQ(v, kMarker);
      expectNoGlErrors("validation");
      ++refused;
    }
  }
  std::printf("%zu texture kinds x %zu slots: %d refused, no GL error\n", kinds.size(),
              std::size(slots), refused);
  for (const Kind& kind : kinds) glDeleteTextures(1, &kind.texture);
  glDeleteTextures(1, &shadow);
  glDeleteBuffers(1, &buffer);
  glDeleteTextures(1, &water);
}

// After an accepted extreme frame (camera at the world extent, the sun turned far) and after
// refused ones, an ordinary frame is bit-identical to the same frame in a fresh context: the
// god-ray grid pivot keeps no rounding from far positions (it once left the ordinary frames
// 0.26-0.62 off for at least 25 frames).
TEST_F(PostfxRefusalTest, ExtremeFramesLeaveNoTrace) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.02);
  const postfx::FrameDesc ordinary = postfxtest::makeFrame(scene, water, 3);
  Result r = Result::InvalidArgument;
  auto fresh = postfxtest::makeContext(kEverySeabedPass);
  const std::vector<glm::vec4> reference = dispatch(*fresh, scene, ordinary, r);
  ASSERT_EQ(r, Result::Ok);

  auto fx = postfxtest::makeContext(kEverySeabedPass);
  dispatch(*fx, scene, ordinary, r);
  const std::function<void(postfx::FrameDesc&)> extremes[] = {
      [](postfx::FrameDesc& f) { f.camera.position.x = 1e9; },
      [](postfx::FrameDesc& f) { f.camera.position = glm::dvec3(-7.3e8, -2.0, 9.1e8); },
      [](postfx::FrameDesc& f) {
        f.camera.position.x = 1e9;
        f.sun.direction = glm::normalize(glm::dvec3(-0.4, 0.6, 0.5));
      },
      [](postfx::FrameDesc& f) { f.sun.direction = glm::dvec3(0.0, 1.0, 0.0); },
      [](postfx::FrameDesc& f) { f.godRays.gridSpacing = 0.01f; },
      [](postfx::FrameDesc& f) { f.camera.position.x = 1e15; },    // refused
      [](postfx::FrameDesc& f) { f.sun.direction.y = 1e300; },     // refused
      [](postfx::FrameDesc& f) { f.camera.position.y = -1e300; },  // refused
  };
  int index = 0;
  for (const auto& extreme : extremes) {
    SCOPED_TRACE(index++);
    postfx::FrameDesc frame = ordinary;
    extreme(frame);
    dispatch(*fx, scene, frame, r);
    if (r == Result::Ok) {
      EXPECT_EQ(
          nonFinite(postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height)),
          0);
    }
    EXPECT_TRUE(sameBits(dispatch(*fx, scene, ordinary, r), reference))
        << "the next ordinary frame differs from a fresh context's";
    EXPECT_EQ(r, Result::Ok);
  }
  glDeleteTextures(1, &water);
}

}  // namespace
