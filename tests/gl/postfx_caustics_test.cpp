// Physics properties of the caustics pass on CPU-ray-traced G-buffers, checked per pixel against
// the scene's ground truth and against the shared shader math evaluated on the CPU.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfxtest::Hit;
using postfxtest::kRaw;

class PostfxCausticsTest : public testsupport::GlTest {};

// Camera 2 m under the water looking slightly down: floor, a sphere breaking the surface, sky.
postfxtest::SceneSpec mixedScene() {
  postfxtest::SceneSpec s;
  s.lookDirection = {0.0, -0.1, -1.0};
  s.sphereCenter = {2.0, 0.5, -8.0};
  return s;
}
constexpr double kLevel = -0.5;  // world; the camera is at y = -2

TEST_F(PostfxCausticsTest, NoneAboveWaterOnSkyOrFacingAway) {
  postfxtest::Scene scene(mixedScene());
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  auto fx = postfxtest::makeContext(kRaw);
  const postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, kLevel);
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const int w = scene.spec().width, h = scene.spec().height;
  const auto raw = postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), w, h);
  const glm::dvec3 up = -postfx::detail::refractedSunDown(frame.sun.direction, frame.water.ior);
  const double levelRel = kLevel - scene.spec().camera.y;
  int sky = 0, above = 0, away = 0, lit = 0;
  double litSum = 0.0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      const float v = raw[static_cast<size_t>(y * w + x)];
      ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << x << "," << y << ": " << v;
      const double nDotL = glm::dot(t.normal, up);
      // Margins: a pixel's reconstructed position differs from the ray-traced one by depth
      // quantization (~1e-4 m here) and the normal by RG16_SNORM quantization (~1e-4).
      if (t.hit == Hit::Sky) {
        ++sky;
        EXPECT_EQ(v, 0.0f) << "sky at " << x << "," << y;
      } else if (t.position.y > levelRel + 1e-3) {
        ++above;
        EXPECT_EQ(v, 0.0f) << "above water at " << x << "," << y;
      } else if (nDotL < -1e-3) {
        ++away;
        EXPECT_EQ(v, 0.0f) << "facing away at " << x << "," << y;
      } else if (t.hit == Hit::Floor) {
        ++lit;
        litSum += double(v);
      }
    }
  }
  // The scene must actually contain each case, or the test proves nothing.
  EXPECT_GT(sky, 50);
  EXPECT_GT(above, 50);
  EXPECT_GT(away, 50);
  EXPECT_GT(lit, 1000);
  EXPECT_GT(litSum / lit, 0.1) << "the floor should receive caustics";
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCausticsTest, FlatWaterGivesUniformFactorMatchingSharedMath) {
  postfxtest::SceneSpec spec;
  spec.sphere = false;
  spec.lookDirection = {0.0, -1.0, -0.5};
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.0);
  auto fx = postfxtest::makeContext(kRaw);
  const postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto raw =
      postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);

  // Expected: the shader's formula on the CPU with the flat normal.
  const glm::dvec3 sun = frame.sun.direction;
  const glm::vec3 up(-postfx::detail::refractedSunDown(sun, frame.water.ior));
  const float omega =
      postfx::shared::causticFactor(glm::vec3(sun), glm::vec3(0, 1, 0), 1.0f / frame.water.ior,
                                    frame.caustics.tau, frame.caustics.reflectionWeight);
  EXPECT_NEAR(omega, 1.0f, 1e-6f) << "flat water: both rays unperturbed, a = 0";
  const float depth = static_cast<float>(-(spec.floorY - 0.0));
  const float expected =
      omega * up.y * postfx::shared::causticSurfaceFade(depth, frame.caustics.surfaceFadeDepth);
  int floorPixels = 0;
  for (int i = 0; i < spec.width * spec.height; ++i) {
    if (scene.truth(i % spec.width, i / spec.width).hit != Hit::Floor) continue;
    ++floorPixels;
    // R16F holds ~11 bits: 1e-3 relative.
    ASSERT_NEAR(raw[static_cast<size_t>(i)], expected, 1e-3) << "pixel " << i;
  }
  EXPECT_EQ(floorPixels, spec.width * spec.height);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCausticsTest, BeerLambertPerChannelAlongDepth) {
  postfxtest::SceneSpec spec;
  spec.sphere = false;
  spec.camera = {0.0, -1.0, 0.0};
  spec.lookDirection = {0.0, -1.0, -0.3};
  spec.floorY = -4.0;
  spec.floorY2 = -6.0;
  spec.stepX = 0.0;  // camera-relative x > 0 is 2 m deeper
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 1, 0.0);
  auto fx = postfxtest::makeContext(postfx::Feature::Caustics);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1);
  frame.sun.direction = {0.0, 1.0, 0.0};  // zenith: the path length is the depth itself
  frame.water.absorption = {0.4f, 0.07f, 0.02f};
  // The sun path alone: the view path's factor is PostfxCompositionTest's.
  frame.viewExtinction = postfx::ViewExtinction::Host;
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto hdr = postfxtest::readRgba(scene.target, spec.width, spec.height);
  const glm::vec3 sigma = frame.water.absorption;
  int shallow = 0, deep = 0;
  for (int i = 0; i < spec.width * spec.height; ++i) {
    const postfxtest::PixelTruth& t = scene.truth(i % spec.width, i / spec.width);
    if (t.hit != Hit::Floor) continue;
    const double depthBelow = -(t.position.y + spec.camera.y);
    (depthBelow > 5.0 ? deep : shallow)++;
    // albedo 1, irradiance 2, omega 1, N.L 1, fade 1: the light is 2 * exp(-sigma * d).
    const glm::vec3 expected =
        2.0f * postfx::shared::causticTransmittance(sigma, static_cast<float>(depthBelow));
    for (int c = 0; c < 3; ++c) {
      ASSERT_NEAR(hdr[static_cast<size_t>(i)][c] / expected[c], 1.0, 1e-5)
          << "channel " << c << " pixel " << i << " depth " << depthBelow;
    }
    EXPECT_EQ(hdr[static_cast<size_t>(i)].a, 0.0f) << "alpha must be untouched";
  }
  EXPECT_GT(shallow, 500);
  EXPECT_GT(deep, 500);
  // Hence a receiver 2 m deeper gets exactly exp(-sigma * 2) less, per channel.
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCausticsTest, ShadowMapMasksCaustics) {
  postfxtest::SceneSpec spec;
  spec.sphere = false;
  spec.lookDirection = {0.0, -1.0, -0.3};
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 2, 0.01);
  // Orthographic sun from straight above covering x, z in [-50, 50]; occluders (depth 0, the
  // nearest) over the left half of the map, nothing (depth 1) over the right.
  GLuint shadow = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &shadow);
  glTextureStorage2D(shadow, 1, GL_DEPTH_COMPONENT32F, 64, 64);
  std::vector<float> texels(64 * 64);
  for (int i = 0; i < 64 * 64; ++i) texels[static_cast<size_t>(i)] = (i % 64) < 32 ? 0.0f : 1.0f;
  glTextureSubImage2D(shadow, 0, 0, 0, 64, 64, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
  // The host's own compare mode must not matter: the plugin's sampler decides.
  glTextureParameteri(shadow, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);

  auto fx = postfxtest::makeContext(kRaw | postfx::Feature::ShadowMask);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 2);
  frame.sun.direction = {0.0, 1.0, 0.0};
  frame.shadow.depth = {shadow, GL_DEPTH_COMPONENT32F};
  frame.shadow.depthConvention = postfx::DepthConvention::ForwardNegOneToOne;
  frame.shadow.worldToLightClip =
      glm::ortho(-50.0, 50.0, -50.0, 50.0, 1.0, 300.0) *
      glm::lookAt(glm::dvec3(0, 100, 0), glm::dvec3(0, 0, 0), glm::dvec3(0, 0, -1));
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto raw =
      postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
  int shadowed = 0, lit = 0;
  for (int i = 0; i < spec.width * spec.height; ++i) {
    const postfxtest::PixelTruth& t = scene.truth(i % spec.width, i / spec.width);
    const double worldX = t.position.x + spec.camera.x;
    const float v = raw[static_cast<size_t>(i)];
    // One shadow-map texel (1.6 m) of margin around the edge, where PCF blends.
    if (worldX < -1.6) {
      ++shadowed;
      EXPECT_EQ(v, 0.0f) << "in shadow, pixel " << i;
    } else if (worldX > 1.6) {
      ++lit;
      EXPECT_GT(v, 0.0f) << "lit, pixel " << i;
    }
  }
  EXPECT_GT(shadowed, 1000);
  EXPECT_GT(lit, 1000);
  glDeleteTextures(1, &shadow);
  glDeleteTextures(1, &water);
}

// Runs one convention/encoding and returns the raw caustic factor.
std::vector<float> rawFor(int convention, int encoding, GLuint water) {
  postfxtest::SceneSpec spec = mixedScene();
  spec.depthConvention = convention;
  spec.normalEncoding = encoding;
  postfxtest::Scene scene(spec);
  auto fx = postfxtest::makeContext(kRaw, convention, encoding);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, kLevel);
  // Pinned rather than the default: the tolerances below are derived for this tightening (a
  // larger tau steepens omega and magnifies the 1/255 UNORM normal quantization with it).
  frame.caustics.tau = 60.0f;
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  return postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height);
}

TEST_F(PostfxCausticsTest, OtherDepthConventionAndNormalEncodingGiveSameCaustics) {
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  const auto reference = rawFor(0, 0, water);  // reverse-Z, octahedral RG16_SNORM
  struct Variant {
    int convention, encoding;
    double maxTolerance;
  };
  // Tolerances: xyz float normals match octahedral snorm to ~1e-4, so only R16F rounding and
  // depth precision remain; RGBA8 UNORM normals are quantized to 1/255 (~0.5 degree), which
  // moves N.L and the tri-planar weights by up to ~1e-2.
  const Variant variants[] = {{0, 1, 0.01}, {1, 0, 0.01}, {2, 0, 0.01}, {2, 2, 0.03}, {1, 1, 0.01}};
  for (const Variant& v : variants) {
    SCOPED_TRACE("convention " + std::to_string(v.convention) + " encoding " +
                 std::to_string(v.encoding));
    const auto other = rawFor(v.convention, v.encoding, water);
    double maxDiff = 0.0, sumDiff = 0.0;
    for (size_t i = 0; i < reference.size(); ++i) {
      const double d = std::abs(double(reference[i]) - double(other[i]));
      maxDiff = std::max(maxDiff, d);
      sumDiff += d;
    }
    EXPECT_LE(maxDiff, v.maxTolerance);
    EXPECT_LE(sumDiff / double(reference.size()), 2e-3);
  }
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCausticsTest, DispersionSplitsChannelsOnlyWhenIorsDiffer) {
  postfxtest::Scene scene(mixedScene());
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  const int w = scene.spec().width, h = scene.spec().height;
  auto plain = postfxtest::makeContext(postfx::Feature::Caustics);
  auto dispersive =
      postfxtest::makeContext(postfx::Feature::Caustics | postfx::Feature::Dispersion);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, kLevel);
  ASSERT_EQ(postfx::dispatch(*plain, frame), postfx::Result::Ok);
  const auto plainHdr = postfxtest::readRgba(scene.target, w, h);

  scene.clearTarget(glm::vec4(0.0f));
  frame.water.iorRgb = glm::vec3(frame.water.ior);
  ASSERT_EQ(postfx::dispatch(*dispersive, frame), postfx::Result::Ok);
  const auto sameIor = postfxtest::readRgba(scene.target, w, h);
  // Same math, but the three-channel variant may contract differently: allow float rounding.
  for (size_t i = 0; i < plainHdr.size(); ++i)
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(plainHdr[i][c], sameIor[i][c], 1e-5f) << i;

  scene.clearTarget(glm::vec4(0.0f));
  frame.water.iorRgb = {1.30f, 1.333f, 1.37f};
  ASSERT_EQ(postfx::dispatch(*dispersive, frame), postfx::Result::Ok);
  const auto split = postfxtest::readRgba(scene.target, w, h);
  // Green keeps the plain IOR, so it is unchanged; red and blue refract differently.
  double redChange = 0.0, blueChange = 0.0;
  for (size_t i = 0; i < split.size(); ++i) {
    ASSERT_NEAR(split[i].g, plainHdr[i].g, 1e-5f) << i;
    redChange += double(std::abs(split[i].r - plainHdr[i].r));
    blueChange += double(std::abs(split[i].b - plainHdr[i].b));
  }
  EXPECT_GT(redChange, 1e-3);
  EXPECT_GT(blueChange, 1e-3);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCausticsTest, BenchmarkFloorAddsExactlyNothing) {
  postfxtest::Scene scene(mixedScene());
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  const int w = scene.spec().width, h = scene.spec().height;
  auto plain = postfxtest::makeContext(postfx::Feature::Caustics);
  auto withFloor =
      postfxtest::makeContext(postfx::Feature::Caustics | postfx::testing::BenchmarkFloor);
  const postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, kLevel);
  ASSERT_EQ(postfx::dispatch(*plain, frame), postfx::Result::Ok);
  const auto a = postfxtest::readRgba(scene.target, w, h);
  scene.clearTarget(glm::vec4(0.0f));
  ASSERT_EQ(postfx::dispatch(*withFloor, frame), postfx::Result::Ok);
  const auto b = postfxtest::readRgba(scene.target, w, h);
  for (size_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], b[i]) << i;
  glDeleteTextures(1, &water);
}

TEST_F(PostfxCausticsTest, SkipsWhenNothingIsUnderwaterInView) {
  postfxtest::SceneSpec spec;
  spec.camera = {0.0, 50.0, 0.0};
  spec.lookDirection = {0.0, 0.5, -1.0};  // looking up: the frustum never reaches the water
  spec.sphere = false;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(32, 1, 0.01);
  auto fx = postfxtest::makeContext(kRaw);
  const postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 1);
  scene.clearTarget(glm::vec4(0.5f));
  for (int i = 0; i < 6; ++i) ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok);
  const postfx::PassStats& caustics = postfx::stats(*fx).pass(postfx::Pass::Caustics);
  EXPECT_TRUE(caustics.skipped);
  EXPECT_EQ(caustics.lastMs, 0.0);
  EXPECT_EQ(caustics.medianMs, 0.0);
  for (float v :
       postfxtest::readRed(postfx::testing::rawCausticTexture(*fx), spec.width, spec.height))
    ASSERT_EQ(v, 0.0f);
  for (const glm::vec4& p : postfxtest::readRgba(scene.target, spec.width, spec.height))
    ASSERT_EQ(p, glm::vec4(0.5f));
  glDeleteTextures(1, &water);
}

}  // namespace
