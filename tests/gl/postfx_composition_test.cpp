// The composition contract of FrameDesc::viewExtinction (postfx/frame_desc.h;
// docs/integration.md, "Composition in your frame"): every piece of light dispatch() adds is
// attenuated along the view ray exactly once. A flat-water frame is checked pixel by pixel
// against the documented model's analytic radiance; the Host mode adds the same light without
// the view-path factor (so a fog after dispatch applies it once); god rays, whose extinction is
// part of their in-scattering integral, are refused in the Host mode rather than attenuated
// twice.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

class PostfxCompositionTest : public testsupport::GlTest {};

constexpr double kLevel = 0.0;

postfxtest::SceneSpec floorScene() {
  postfxtest::SceneSpec spec;
  spec.sphere = false;
  spec.camera = {0.0, -2.0, 0.0};  // under water: the whole view ray is submerged
  spec.floorY = -7.0;              // world: 7 m under the level
  spec.farPlane = 60.0;  // view transmittance down to ~exp(-0.32 * 60): still a normal float
  // White: the scene stores albedo as sRGB bytes, so only 0 and 1 read back exactly.
  spec.albedo = glm::vec3(1.0f);
  return spec;
}

postfx::FrameDesc flatFrame(const postfxtest::Scene& scene, GLuint water) {
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2, {}, kLevel);
  frame.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, -0.2));
  frame.sun.irradiance = glm::vec3(3.0f, 2.5f, 2.0f);
  frame.caustics.intensity = 0.8f;
  frame.caustics.surfaceFadeDepth = 0.0f;
  frame.water.absorption = glm::vec3(0.3f, 0.06f, 0.02f);
  frame.water.scattering = glm::vec3(0.02f, 0.03f, 0.05f);
  return frame;
}

// The documented model for flat water (omega = 1, no shadow map, no fade), per channel:
//   albedo (1 here) E intensity (n.l) exp(-a d / cos theta_t) exp(-sigma_t * view length under
//   water).
glm::dvec3 analyticRadiance(const postfx::FrameDesc& f, const postfxtest::PixelTruth& t,
                            const glm::dvec3& cameraWorld, bool viewExtinction) {
  const glm::dvec3 toSun = glm::normalize(f.sun.direction);
  const glm::dvec3 down = glm::refract(-toSun, glm::dvec3(0, 1, 0), 1.0 / double(f.water.ior));
  const glm::dvec3 l = -down;  // toward the refracted sun
  const double depth = f.water.level - (cameraWorld.y + t.position.y);
  const double viewLength = glm::length(t.position);  // camera under water: all of it
  glm::dvec3 out;
  for (int c = 0; c < 3; ++c) {
    const double a = f.water.absorption[c], sigmaT = a + double(f.water.scattering[c]);
    out[c] = double(f.sun.irradiance[c]) * double(f.caustics.intensity) *
             std::max(glm::dot(t.normal, l), 0.0) * std::exp(-a * depth / l.y) *
             (viewExtinction ? std::exp(-sigmaT * viewLength) : 1.0);
  }
  return out;
}

TEST_F(PostfxCompositionTest, FlatWaterMatchesTheDocumentedModelAttenuatedOnce) {
  const postfxtest::SceneSpec spec = floorScene();
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.0);  // flat
  auto fx = postfxtest::makeContext(postfx::Feature::Caustics);
  postfx::FrameDesc frame = flatFrame(scene, water);

  std::vector<glm::vec4> added[2];
  const postfx::ViewExtinction modes[2] = {postfx::ViewExtinction::Plugin,
                                           postfx::ViewExtinction::Host};
  for (int m = 0; m < 2; ++m) {
    frame.viewExtinction = modes[m];
    scene.clearTarget(glm::vec4(0.0f));
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    added[m] = postfxtest::readRgba(scene.target, spec.width, spec.height);
  }
  double worstPlugin = 0.0, worstHost = 0.0, minTransmittance = 1.0;
  int floorPixels = 0;
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      const size_t i = size_t(y) * spec.width + x;
      if (t.hit != postfxtest::Hit::Floor) continue;
      ++floorPixels;
      const glm::dvec3 plugin = analyticRadiance(frame, t, spec.camera, true);
      const glm::dvec3 host = analyticRadiance(frame, t, spec.camera, false);
      for (int c = 0; c < 3; ++c) {
        // Float shader math against double, a D32F depth and an RG16_SNORM normal (measured
        // 3e-6): 2e-4 leaves room for drivers, far below a missing or doubled factor.
        worstPlugin = std::max(worstPlugin, std::abs(double(added[0][i][c]) / plugin[c] - 1.0));
        worstHost = std::max(worstHost, std::abs(double(added[1][i][c]) / host[c] - 1.0));
        minTransmittance = std::min(minTransmittance, plugin[c] / host[c]);
      }
    }
  }
  std::printf(
      "flat water, %d floor pixels: worst relative error against the analytic radiance %.2e "
      "(plugin attenuates), %.2e (host fogs); view transmittance down to %.2e\n",
      floorPixels, worstPlugin, worstHost, minTransmittance);
  EXPECT_GT(floorPixels, spec.width * spec.height / 3);
  EXPECT_LT(minTransmittance, 0.2) << "the scene must make the view-path factor matter";
  EXPECT_LT(worstPlugin, 2e-4);
  EXPECT_LT(worstHost, 2e-4);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCompositionTest, HostFogWithGodRaysIsRefusedAndDrawsNothing) {
  const postfxtest::SceneSpec spec = floorScene();
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.0);
  auto fx = postfxtest::makeContext(postfx::Feature::Caustics | postfx::Feature::GodRays);
  postfx::FrameDesc frame = flatFrame(scene, water);
  frame.viewExtinction = postfx::ViewExtinction::Host;
  scene.clearTarget(glm::vec4(0.25f));
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(fx.get())).find("viewExtinction"), std::string::npos);
  for (const glm::vec4& v : postfxtest::readRgba(scene.target, spec.width, spec.height))
    ASSERT_EQ(v, glm::vec4(0.25f)) << "a refused frame drew";
  // The same host with its god rays off may fog after dispatch.
  frame.godRays.enabled = false;
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  glDeleteTextures(1, &water);
}

}  // namespace
