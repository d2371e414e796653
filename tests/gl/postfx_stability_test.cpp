// Stiff and extreme inputs: the output stays finite and bounded (raw factor in [0, 1], added
// light at most albedo * irradiance * intensity), and a scene 1e6 m from the origin renders the
// same as at the origin.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <functional>
#include <limits>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfxtest::kRaw;

class PostfxStabilityTest : public testsupport::GlTest {};

struct StiffCase {
  const char* name;
  std::function<void(postfxtest::SceneSpec&)> scene;
  std::function<void(postfx::FrameDesc&)> frame;
  bool nanWater = false;
  double amplitude = 0.02;
};

glm::dvec3 sunAtElevation(double degrees) {
  const double e = glm::radians(degrees);
  return {std::cos(e) * 0.8, std::sin(e), std::cos(e) * 0.6};
}

TEST_F(PostfxStabilityTest, StiffCasesStayFiniteAndBounded) {
  auto none = [](auto&) {};
  const StiffCase cases[] = {
      {"sun at zenith", none,
       [](postfx::FrameDesc& f) {
         f.sun.direction = {0, 1, 0};
       }},
      {"sun grazing 0.01 deg", none,
       [](postfx::FrameDesc& f) { f.sun.direction = sunAtElevation(0.01); }},
      {"sun below horizon", none,
       [](postfx::FrameDesc& f) { f.sun.direction = sunAtElevation(-5.0); }},
      {"tau 0", none, [](postfx::FrameDesc& f) { f.caustics.tau = 0.0f; }},
      {"tau 1e6", none, [](postfx::FrameDesc& f) { f.caustics.tau = 1e6f; }},
      {"water all zero", none, none, false, 0.0},
      {"water all NaN", none, none, true},
      {"steep water", none, none, false, 5.0},
      {"G-buffer normal zero", [](postfxtest::SceneSpec& s) { s.zeroNormals = true; }, none},
      {"depth at far plane", [](postfxtest::SceneSpec& s) { s.allSky = true; }, none},
      {"camera 1e-4 below level", none,
       [](postfx::FrameDesc& f) { f.water.level = f.camera.position.y + 1e-4; }},
      {"camera 1e-4 above level", none,
       [](postfx::FrameDesc& f) { f.water.level = f.camera.position.y - 1e-4; }},
      {"camera exactly at level", none,
       [](postfx::FrameDesc& f) { f.water.level = f.camera.position.y; }},
      {"no surface fade, full reflection", none,
       [](postfx::FrameDesc& f) {
         f.caustics.surfaceFadeDepth = 0.0f;
         f.caustics.reflectionWeight = 1.0f;
       }},
      {"opaque water", none, [](postfx::FrameDesc& f) { f.water.absorption = glm::vec3(1e3f); }},
  };
  for (const StiffCase& c : cases) {
    SCOPED_TRACE(c.name);
    postfxtest::SceneSpec spec;
    spec.lookDirection = {0.0, -0.3, -1.0};
    spec.sphereCenter = {2.0, 0.5, -8.0};
    c.scene(spec);
    for (int convention = 0; convention < 3; convention += 2) {
      spec.depthConvention = convention;
      postfxtest::Scene scene(spec);
      const GLuint water = postfxtest::makeWaterTexture(32, 3, c.amplitude, c.nanWater);
      auto fx = postfxtest::makeContext(kRaw | postfx::Feature::Dispersion, convention);
      postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
      c.frame(frame);
      ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
      const float bound = 2.0f * frame.caustics.intensity;  // albedo 1, irradiance 2
      for (float v :
           postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height))
        ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << "raw " << v;
      for (const glm::vec4& p : postfxtest::readRgba(scene.target, spec.width, spec.height))
        for (int ch = 0; ch < 4; ++ch)
          ASSERT_TRUE(p[ch] >= 0.0f && p[ch] <= bound) << "hdr " << p[ch] << " channel " << ch;
      glDeleteTextures(1, &water);
    }
  }
}

TEST_F(PostfxStabilityTest, MillionMetresFromOriginMatchesOrigin) {
  postfxtest::SceneSpec spec;
  spec.lookDirection = {0.0, -0.4, -1.0};
  spec.sphereCenter = {2.0, 0.5, -8.0};
  spec.width = 256;
  spec.height = 144;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.02);
  auto fx = postfxtest::makeContext(kRaw);
  // 1e6 is a whole number of every tile (40, 10, 2.5 m), so the water is the same there.
  const glm::dvec3 offset(1e6, 1e6, -1e6);
  const postfx::FrameDesc atOrigin = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
  ASSERT_EQ(postfx::dispatch(*fx, atOrigin), postfx::Result::Ok);
  const auto a =
      postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
  const auto hdrA = postfxtest::readRgba(scene.target, spec.width, spec.height);
  scene.clearTarget(glm::vec4(0.0f));
  postfx::FrameDesc far = postfxtest::makeFrame(scene, water, 3, offset, -0.5);
  ASSERT_EQ(postfx::dispatch(*fx, far), postfx::Result::Ok);
  const auto b =
      postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
  const auto hdrB = postfxtest::readRgba(scene.target, spec.width, spec.height);
  double maxRaw = 0.0, maxHdr = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    maxRaw = std::max(maxRaw, std::abs(double(a[i]) - double(b[i])));
    for (int c = 0; c < 3; ++c)
      maxHdr = std::max(maxHdr, std::abs(double(hdrA[i][c]) - double(hdrB[i][c])) / 2.0);
  }
  EXPECT_LE(maxRaw, 1.0 / 255.0);
  EXPECT_LE(maxHdr, 1.0 / 255.0);  // relative to the irradiance (2)

  // And the far scene without the tile reduction would not match: a float camera position
  // at 1e6 m has 6 cm steps. (Documented contrast, not a property of the plugin.)
  glDeleteTextures(1, &water);
}

}  // namespace
