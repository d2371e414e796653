// God rays (Feature::GodRays): world-snapped sampling is temporally stable, the pass is skipped
// when there is nothing to light, the shadow map blocks shafts, stiff inputs stay finite, a
// scene 1e6 m away matches the origin, half resolution matches full, bad settings are refused
// and GL state survives. Small targets keep llvmpipe fast.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <vector>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfx::Feature;
using postfx::GodRayResolution;
using postfx::Result;

constexpr GodRayResolution kResolutions[] = {GodRayResolution::Full, GodRayResolution::Half,
                                             GodRayResolution::Quarter};

class PostfxGodRaysTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  postfxtest::HostState host_;
};

postfxtest::SceneSpec smallSpec() {
  postfxtest::SceneSpec spec;
  spec.width = 64;
  spec.height = 36;
  spec.lookDirection = {0.0, -0.25, -1.0};
  spec.sphereCenter = {2.0, -1.0, -8.0};
  return spec;
}

// Dispatches `frame` into a cleared target and returns the light added (rgb).
std::vector<glm::vec4> render(postfx::Context& fx, const postfxtest::Scene& scene,
                              const postfx::FrameDesc& frame) {
  scene.clearTarget(glm::vec4(0.0f));
  EXPECT_EQ(postfx::dispatch(fx, frame), Result::Ok) << postfx::lastError(&fx);
  return postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height);
}

double meanLight(const std::vector<glm::vec4>& image) {
  double sum = 0.0;
  for (const glm::vec4& p : image) sum += double(p.r + p.g + p.b);
  return sum / double(image.size());
}

bool allFiniteNonNegative(const std::vector<glm::vec4>& image) {
  for (const glm::vec4& p : image)
    for (int c = 0; c < 3; ++c)
      if (!(std::isfinite(p[c]) && p[c] >= 0.0f)) return false;
  return true;
}

// Mean absolute frame-to-frame change of the god-ray buffer while the camera steps forward.
double flicker(postfx::testing::GodRaySampling sampling, double* level) {
  postfxtest::SceneSpec spec = smallSpec();
  spec.sphere = false;
  postfxtest::Scene scene(spec);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  EXPECT_EQ(postfx::testing::setGodRaySampling(*fx, sampling), Result::Ok);
  // Horizontal steps toward where the camera looks: the floor (an infinite plane at a fixed world
  // height) gives the same G-buffer every frame, so a static world is seen from a moving camera.
  const glm::dvec3 forward =
      glm::normalize(glm::dvec3(spec.lookDirection.x, 0.0, spec.lookDirection.z));
  std::vector<glm::vec4> previous;
  double change = 0.0, sum = 0.0;
  const int steps = 12;
  for (int i = 0; i <= steps; ++i) {
    // The camera moves 2 cm a frame.
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, forward * (0.02 * i), 0.0);
    frame.godRays.sampleCount = 16;
    frame.godRays.gridSpacing = 0.5f;
    const std::vector<glm::vec4> image = render(*fx, scene, frame);
    if (!previous.empty()) {
      double d = 0.0;
      for (size_t p = 0; p < image.size(); ++p)
        d += std::abs(double(image[p].g) - double(previous[p].g));
      change += d / double(image.size());
    }
    sum += meanLight(image);
    previous = image;
  }
  glDeleteTextures(1, &water);
  *level = sum / (steps + 1);
  return change / steps;
}

TEST_F(PostfxGodRaysTest, WorldSnappedSamplingFlickersLessThanUniform) {
  double snappedLevel = 0.0, uniformLevel = 0.0;
  const double snapped = flicker(postfx::testing::GodRaySampling::WorldGrid, &snappedLevel);
  const double uniform = flicker(postfx::testing::GodRaySampling::UniformAlongRay, &uniformLevel);
  std::printf(
      "god-ray frame-to-frame change (mean |dG| per pixel, 2 cm camera steps): "
      "world-snapped %.3g, uniform %.3g, ratio %.3f (mean light %.3g / %.3g)\n",
      snapped, uniform, snapped / uniform, snappedLevel, uniformLevel);
  RecordProperty("flicker_snapped", std::to_string(snapped));
  RecordProperty("flicker_uniform", std::to_string(uniform));
  ASSERT_GT(snappedLevel, 1e-3) << "the test must see god rays";
  EXPECT_LT(snapped, 0.5 * uniform);
}

TEST_F(PostfxGodRaysTest, SkippedWithNothingToLight) {
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays | postfx::testing::BenchmarkFloor);
  const postfx::FrameStats& stats = postfx::stats(*fx);
  ASSERT_TRUE(stats.pass(postfx::Pass::GodRays).present);
  struct Case {
    const char* name;
    std::function<void(postfxtest::SceneSpec&)> scene;
    std::function<void(postfx::FrameDesc&)> frame;
  };
  const Case cases[] = {
      {"camera above water looking up",
       [](postfxtest::SceneSpec& s) {
         s.lookDirection = {0.0, 1.0, -0.2};
       },
       [](postfx::FrameDesc& f) { f.water.level = f.camera.position.y - 5.0; }},
      {"sun below the horizon", [](postfxtest::SceneSpec&) {},
       [](postfx::FrameDesc& f) {
         f.sun.direction = {0.3, -0.2, 0.1};
       }},
      {"disabled", [](postfxtest::SceneSpec&) {},
       [](postfx::FrameDesc& f) { f.godRays.enabled = false; }},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    postfxtest::SceneSpec spec = smallSpec();
    c.scene(spec);
    postfxtest::Scene scene(spec);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    c.frame(frame);
    for (int i = 0; i < postfx::kTimerRingDepth + 2; ++i) render(*fx, scene, frame);
    glFinish();
    const std::vector<glm::vec4> image = render(*fx, scene, frame);
    EXPECT_EQ(meanLight(image), 0.0);
    EXPECT_TRUE(stats.pass(postfx::Pass::GodRays).skipped);
    EXPECT_EQ(stats.pass(postfx::Pass::GodRays).lastMs, 0.0);
  }
  glDeleteTextures(1, &water);
}

// frame_desc.h's contract at every resolution: no light on anything above the water seen from
// above it. A ball straddles the level, so texels of its wall just under the waterline sit beside
// pixels just above it at the same distance: the reduced march's upsample once carried a
// half-float step of shaft light onto the wall 9 mm above the water at Quarter resolution.
TEST_F(PostfxGodRaysTest, NothingAboveTheWaterIsLitFromAboveAtAnyResolution) {
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  postfxtest::SceneSpec spec = smallSpec();
  spec.width = 160;
  spec.height = 90;
  spec.camera = {0.0, 0.4, 0.0};
  spec.lookDirection = {0.0, -0.3, -1.0};
  spec.sphereCenter = {0.3, -0.4, -5.0};  // world y = 0: the level cuts it in half
  spec.sphereRadius = 1.5;
  postfxtest::Scene scene(spec);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  for (const postfx::GodRayResolution resolution :
       {postfx::GodRayResolution::Full, postfx::GodRayResolution::Half,
        postfx::GodRayResolution::Quarter}) {
    SCOPED_TRACE(static_cast<int>(resolution));
    frame.godRays.resolution = resolution;
    const std::vector<glm::vec4> image = render(*fx, scene, frame);
    int above = 0, lit = 0, litBelow = 0;
    for (int y = 0; y < spec.height; ++y)
      for (int x = 0; x < spec.width; ++x) {
        const postfxtest::PixelTruth& t = scene.truth(x, y);
        const glm::vec4& p = image[static_cast<size_t>(y) * spec.width + x];
        const bool light = p.r + p.g + p.b > 0.0f;
        const double worldY = spec.camera.y + t.position.y;
        if (t.hit != postfxtest::Hit::Sky && worldY > frame.water.level + 1e-4) {
          ++above;
          lit += light ? 1 : 0;
        } else if (light) {
          ++litBelow;
        }
      }
    EXPECT_GT(above, 100) << "the scene shows the ball above the water";
    EXPECT_GT(litBelow, 100) << "and shafts below it";
    EXPECT_EQ(lit, 0) << "pixels above the water with god-ray light";
  }
  glDeleteTextures(1, &water);
}

// A shadow map in the forward [0,1] convention whose left half (light-space x < 0) holds an
// occluder at depth 0 and whose right half is empty (depth 1); `full` occludes everything.
GLuint makeShadowMap(bool left, bool right) {
  const int size = 16;
  std::vector<float> texels(size * size);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      texels[y * size + x] = (x < size / 2 ? left : right) ? 0.0f : 1.0f;
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTextureSubImage2D(t, 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
  return t;
}

TEST_F(PostfxGodRaysTest, ShadowMapBlocksShafts) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays | Feature::ShadowMask);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  // Light clip x = world x / 200 (left half: x < 0), y = world z / 200 (the whole march fits),
  // depth 0.5 everywhere.
  glm::dmat4 m(0.0);
  m[0][0] = 1.0 / 200.0;
  m[2][1] = 1.0 / 200.0;
  m[3][2] = 0.5;
  m[3][3] = 1.0;
  frame.shadow.worldToLightClip = m;
  frame.shadow.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  double light[4] = {};
  const bool occluders[4][2] = {{false, false}, {true, false}, {false, true}, {true, true}};
  for (int i = 0; i < 4; ++i) {
    const GLuint map = makeShadowMap(occluders[i][0], occluders[i][1]);
    frame.shadow.depth = {map, GL_DEPTH_COMPONENT32F};
    light[i] = meanLight(render(*fx, scene, frame));
    glDeleteTextures(1, &map);
  }
  std::printf("mean god-ray light: no occluder %.4g, left half %.4g, right half %.4g, all %.4g\n",
              light[0], light[1], light[2], light[3]);
  EXPECT_GT(light[0], 1e-3);
  EXPECT_LT(light[1], 0.95 * light[0]);
  EXPECT_LT(light[2], 0.95 * light[0]);
  EXPECT_NEAR(light[1] + light[2], light[0], 0.02 * light[0]) << "the halves partition the light";
  EXPECT_EQ(light[3], 0.0) << "no shafts behind a full occluder";
  glDeleteTextures(1, &water);
}

TEST_F(PostfxGodRaysTest, GuardedCasesStayFiniteAndBounded) {
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  const GLuint nanWater = postfxtest::makeWaterTexture(32, 3, 0.01, /*nan=*/true);
  struct Case {
    const char* name;
    std::function<void(postfx::FrameDesc&)> frame;
    bool allSky = false;
  };
  auto sunAt = [](double degrees) {
    const double e = glm::radians(degrees);
    return glm::dvec3(std::cos(e) * 0.8, std::sin(e), std::cos(e) * 0.6);
  };
  const Case cases[] = {
      {"sun at zenith: rays parallel to a plane family",
       [](postfx::FrameDesc& f) {
         f.sun.direction = {0, 1, 0};
       }},
      {"sun grazing 0.01 deg", [&](postfx::FrameDesc& f) { f.sun.direction = sunAt(0.01); }},
      {"sun below horizon", [&](postfx::FrameDesc& f) { f.sun.direction = sunAt(-3.0); }},
      {"camera exactly on a plane",
       [](postfx::FrameDesc& f) {
         f.sun.direction = {0, 1, 0};
         f.camera.position = {2.0, -2.0, -3.0};
         f.godRays.gridSpacing = 0.5f;
       }},
      {"zero-length march (camera at the level, sky above)",
       [](postfx::FrameDesc& f) { f.water.level = f.camera.position.y; }, true},
      {"very long march, fine grid",
       [](postfx::FrameDesc& f) {
         f.godRays.maxDistance = 1e5f;
         f.godRays.gridSpacing = 0.01f;
         f.godRays.sampleCount = 64;
       },
       true},
      {"coarse grid, few samples",
       [](postfx::FrameDesc& f) {
         f.godRays.gridSpacing = 1e3f;
         f.godRays.sampleCount = 4;
       }},
      {"no fades, dither",
       [](postfx::FrameDesc& f) {
         f.godRays.surfaceFadeDistance = 0.0f;
         f.godRays.depthFadeDistance = 0.0f;
         f.godRays.dither = true;
       }},
      {"opaque water", [](postfx::FrameDesc& f) { f.water.absorption = glm::vec3(1e3f); }},
      {"no scattering", [](postfx::FrameDesc& f) { f.water.scattering = glm::vec3(0.0f); }},
      {"NaN water texture", [&](postfx::FrameDesc& f) { f.water.texture.texture = nanWater; }},
      {"camera 1e6 m away", [](postfx::FrameDesc& f) { f.camera.position += 1e6; }},
  };
  for (const Case& c : cases) {
    for (GodRayResolution resolution : kResolutions) {
      SCOPED_TRACE(std::string(c.name) + " (1/" + std::to_string(int(resolution)) + " res)");
      postfxtest::SceneSpec spec = smallSpec();
      spec.allSky = c.allSky;
      postfxtest::Scene scene(spec);
      auto fx = postfxtest::makeContext(Feature::GodRays);
      postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
      frame.godRays.resolution = resolution;
      c.frame(frame);
      const std::vector<glm::vec4> image = render(*fx, scene, frame);
      ASSERT_TRUE(allFiniteNonNegative(image));
      // In-scattering cannot exceed E * intensity * sigma_s / sigma_t <= E * intensity.
      const float bound = 2.0f * frame.godRays.intensity;
      for (const glm::vec4& p : image) ASSERT_LE(std::max(p.r, std::max(p.g, p.b)), bound);
    }
  }
  const GLuint textures[] = {water, nanWater};
  glDeleteTextures(2, textures);
}

TEST_F(PostfxGodRaysTest, FarFromOriginMatchesOrigin) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  auto frameAt = [&](const glm::dvec3& offset) {
    postfx::FrameDesc f = postfxtest::makeFrame(scene, water, 3, offset, -0.5);
    // Zenith sun: the grid axes are world x and z, so an offset that is a whole number of
    // tiles (40, 10, 2.5 m) and of grid cells (0.5 m) gives the same picture exactly.
    f.sun.direction = {0.0, 1.0, 0.0};
    f.godRays.gridSpacing = 0.5f;
    return f;
  };
  const std::vector<glm::vec4> origin = render(*fx, scene, frameAt(glm::dvec3(0.0)));
  const std::vector<glm::vec4> far = render(*fx, scene, frameAt({1e6, 0.0, -1e6}));
  double maxDiff = 0.0, maxValue = 0.0;
  for (size_t i = 0; i < origin.size(); ++i) {
    maxDiff = std::max(maxDiff, double(std::abs(origin[i].g - far[i].g)));
    maxValue = std::max(maxValue, double(origin[i].g));
  }
  std::printf("1e6 m offset: max |difference| %.3g of max %.3g\n", maxDiff, maxValue);
  ASSERT_GT(maxValue, 1e-3);
  // float32 target; the GPU sees the same camera-relative values, so only rounding of the
  // double-to-float phases remains.
  EXPECT_LE(maxDiff, 1e-3 * maxValue);
  glDeleteTextures(1, &water);
}

TEST_F(PostfxGodRaysTest, ReducedResolutionIsCloseToFull) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
  frame.godRays.resolution = GodRayResolution::Full;
  const std::vector<glm::vec4> full = render(*fx, scene, frame);
  // Shafts are smooth across the screen; what differs is the grid pattern's finest detail and
  // silhouettes: 15% of the mean light is a loose bound on that at half resolution (10% measured),
  // twice that at quarter, whose texels are twice as wide (24% measured: 4 pixels of 256).
  const struct {
    GodRayResolution resolution;
    double bound;
  } cases[] = {{GodRayResolution::Half, 0.15}, {GodRayResolution::Quarter, 0.3}};
  for (const auto& c : cases) {
    frame.godRays.resolution = c.resolution;
    const std::vector<glm::vec4> reduced = render(*fx, scene, frame);
    double diff = 0.0, level = 0.0;
    for (size_t i = 0; i < full.size(); ++i) {
      diff += std::abs(double(full[i].g) - double(reduced[i].g));
      level += double(full[i].g);
    }
    std::printf("1/%d vs full resolution: mean |difference| %.3g, mean light %.3g (%.1f%%)\n",
                int(c.resolution), diff / double(full.size()), level / double(full.size()),
                100.0 * diff / level);
    ASSERT_GT(level, 0.0);
    EXPECT_LT(diff / level, c.bound);
  }
  glDeleteTextures(1, &water);
}

// The light is linear in the sun's irradiance at every resolution, in whatever units the host
// lights its frame: the reduced march stores light per unit of the sun's, so a host in
// photometric units (1e5 lux and more) does not overflow the half floats it is kept in.
TEST_F(PostfxGodRaysTest, LightIsLinearInTheSunsIrradianceAtEveryResolution) {
  postfxtest::Scene scene(smallSpec(), GL_RGBA32F);
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3, {}, -0.5);
  for (GodRayResolution resolution : kResolutions) {
    frame.godRays.resolution = resolution;
    frame.sun.irradiance = glm::vec3(1.0f);
    const std::vector<glm::vec4> unit = render(*fx, scene, frame);
    constexpr float kScale = 1e6f;  // 1e6 x the unit light: far past a half's 65504
    frame.sun.irradiance = glm::vec3(kScale);
    const std::vector<glm::vec4> bright = render(*fx, scene, frame);
    double level = 0.0, worst = 0.0;
    for (size_t i = 0; i < unit.size(); ++i) {
      level = std::max(level, double(unit[i].g));
      ASSERT_TRUE(std::isfinite(bright[i].g)) << "pixel " << i;
      worst = std::max(worst, std::abs(double(bright[i].g) / double(kScale) - double(unit[i].g)));
    }
    ASSERT_GT(level, 1e-3) << "the test must see god rays";
    // float rounding of the scale only: the same halves are stored for both.
    EXPECT_LE(worst, 1e-5 * level) << "1/" << int(resolution);
  }
  glDeleteTextures(1, &water);
}

TEST_F(PostfxGodRaysTest, BadSettingsAreRefusedWithStateUntouched) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx = postfxtest::makeContext(Feature::GodRays);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::function<void(postfx::FrameDesc&)> bad[] = {
      [](postfx::FrameDesc& f) { f.godRays.sampleCount = 3; },
      [](postfx::FrameDesc& f) { f.godRays.sampleCount = 65; },
      [](postfx::FrameDesc& f) { f.godRays.gridSpacing = 0.0f; },
      [&](postfx::FrameDesc& f) { f.godRays.gridSpacing = nan; },
      [](postfx::FrameDesc& f) { f.godRays.intensity = -1.0f; },
      [&](postfx::FrameDesc& f) { f.godRays.surfaceFadeDistance = nan; },
      [](postfx::FrameDesc& f) { f.godRays.depthFadeDistance = -1.0f; },
      [](postfx::FrameDesc& f) { f.godRays.maxDistance = std::numeric_limits<float>::infinity(); },
      [&](postfx::FrameDesc& f) { f.water.scattering = glm::vec3(0.1f, nan, 0.1f); },
  };
  scene.clearTarget(glm::vec4(0.25f));
  host_.set();
  const postfxtest::GlSnapshot before = postfxtest::snapshotGlState();
  // The test hook refuses a value outside its enum the same way.
  EXPECT_EQ(
      postfx::testing::setGodRaySampling(*fx, static_cast<postfx::testing::GodRaySampling>(7)),
      Result::InvalidArgument);
  for (const auto& change : bad) {
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    change(frame);
    EXPECT_EQ(postfx::dispatch(*fx, frame), Result::InvalidArgument);
    const std::string message = postfx::lastError(fx.get());
    EXPECT_TRUE(message.find("godRays") != std::string::npos ||
                message.find("scattering") != std::string::npos)
        << message;
  }
  const postfxtest::GlSnapshot after = postfxtest::snapshotGlState();
  for (const auto& [name, value] : before) EXPECT_EQ(value, after.at(name)) << name;
  host_.reset();
  for (const glm::vec4& p :
       postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height))
    ASSERT_EQ(p.r, 0.25f) << "nothing drawn";
  glDeleteTextures(1, &water);
}

TEST_F(PostfxGodRaysTest, GlStateRestoredWithGodRays) {
  postfxtest::Scene scene(smallSpec());
  const GLuint water = postfxtest::makeWaterTexture(32, 3, 0.01);
  auto fx =
      postfxtest::makeContext(Feature::Caustics | Feature::GodRays |
                              postfx::testing::RawCausticOutput | postfx::testing::BenchmarkFloor);
  for (GodRayResolution resolution : kResolutions) {
    SCOPED_TRACE("1/" + std::to_string(int(resolution)) + " resolution");
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    frame.godRays.resolution = resolution;
    scene.clearTarget(glm::vec4(0.0f));
    host_.set();
    const postfxtest::GlSnapshot before = postfxtest::snapshotGlState();
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    const postfxtest::GlSnapshot after = postfxtest::snapshotGlState();
    for (const auto& [name, value] : before) EXPECT_EQ(value, after.at(name)) << name;
    host_.reset();
    EXPECT_GT(
        meanLight(postfxtest::readRgba(scene.target, scene.spec().width, scene.spec().height)),
        0.0);
  }
  glDeleteTextures(1, &water);
}

}  // namespace
