// Reflected caustics above the water (postfx/reflected_caustics.h): physics and contracts. Flat
// water mirrors exactly R(theta_sun) E onto a surface facing the mirrored sun, whatever its
// height; waves keep that mean and modulate it; the reflected and transmitted fields together
// carry the incident flux; nothing under the water, on the sky, on faces turned up or away, or
// in the shade a pier casts on the water; the feature off (or disabled) changes nothing, bit for
// bit; bad settings are refused with nothing drawn; the memory estimate is what GL holds.
#include <gtest/gtest.h>
#include <postfx/testing.h>
#include <postfx/views.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/context.h"
#include "core/frame_plan.h"
#include "core/gl_sizes.h"
#include "core/memory_estimate.h"
#include "core/shared_math.h"
#include "fuzz/fuzz_values.h"
#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "reflected_caustics/reflected_layout.h"
#include "synthetic_gbuffer.h"

namespace {

using ocean::validation::SyntheticGbuffer;
using ocean::validation::SyntheticScene;
using ocean::validation::SyntheticSurface;

class PostfxReflectedCausticsTest : public testsupport::GlTest {};

constexpr float kIor = 1.333f;
constexpr int kWidth = 96, kHeight = 64;
constexpr glm::vec3 kSunIrradiance{2.0f, 1.5f, 1.0f};
constexpr float kAlbedo = 0.5f;

// The sun 35 degrees up, from +z (the mirrored sun then travels toward -z and up).
glm::dvec3 towardSun() {
  const double e = glm::radians(35.0);
  return glm::dvec3(0.0, std::sin(e), std::cos(e));
}

glm::dvec3 mirrorReversed() {  // l_r: from a receiver down toward the water
  const glm::dvec3 s = towardSun();
  return glm::dvec3(s.x, -s.y, s.z);
}

// Which surface of receiverScene() a pixel shows (SyntheticScene::surfaces order).
enum SurfaceIndex { kCeiling = 0, kDeck = 1, kSeabed = 2, kWall = 3, kSideWall = 4 };

// A camera `cameraY` above the level (world y 0) at the origin, looking along `look`: the
// underside of a pier deck 2 m up (facing down) from z = 0 to -7, its top 2.2 m up (facing up),
// a quay wall at z = -9 facing +z (toward the sun) from below the seabed up to 5 m, the seabed
// 3 m down, and a side wall at x = -4 turned away from the water's light (facing +x and -z);
// sky above the wall. Positions are camera-relative.
SyntheticScene receiverScene(const glm::dvec3& look, double cameraY) {
  SyntheticScene s;
  s.width = kWidth;
  s.height = kHeight;
  s.view =
      glm::dmat4(glm::lookAt(glm::dvec3(0.0), glm::normalize(look), glm::dvec3(0.0, 1.0, 0.0)));
  s.projection = postfxtest::reverseZPerspective(70.0, double(kWidth) / kHeight, 0.05, 200.0);
  s.albedoFormat = GL_RGBA16F;
  s.targetFormat = GL_RGBA32F;
  s.maxDistance = 199.0;
  SyntheticSurface ceiling;
  ceiling.point = {0.0, 2.0 - cameraY, 0.0};
  ceiling.normal = {0.0, -1.0, 0.0};
  ceiling.keep = {0.0, 0.0, 1.0, 7.0};  // z >= -7
  ceiling.albedo = glm::vec3(kAlbedo);
  SyntheticSurface deck = ceiling;
  deck.point.y = 2.2 - cameraY;
  deck.normal = {0.0, 1.0, 0.0};
  SyntheticSurface seabed;
  seabed.point = {0.0, -3.0 - cameraY, 0.0};
  seabed.albedo = glm::vec3(kAlbedo);
  SyntheticSurface wall;
  wall.point = {0.0, 0.0, -9.0};
  wall.normal = {0.0, 0.0, 1.0};
  wall.keep = {0.0, -1.0, 0.0, 5.0 - cameraY};  // y <= 5
  wall.albedo = glm::vec3(kAlbedo);
  SyntheticSurface side;
  side.point = {-4.0, 0.0, 0.0};
  side.normal = glm::normalize(glm::dvec3(0.8, 0.0, -0.6));
  side.keep = {0.0, -1.0, 0.0, 5.0 - cameraY};
  side.albedo = glm::vec3(kAlbedo);
  s.surfaces = {ceiling, deck, seabed, wall, side};
  return s;
}

class OwnedTexture {
 public:
  explicit OwnedTexture(GLuint id) : id_(id) {}
  ~OwnedTexture() { glDeleteTextures(1, &id_); }
  OwnedTexture(const OwnedTexture&) = delete;
  OwnedTexture& operator=(const OwnedTexture&) = delete;
  operator GLuint() const { return id_; }

 private:
  GLuint id_;
};

postfx::FrameDesc frameFor(const SyntheticGbuffer& g, const SyntheticScene& s, double cameraY,
                           GLuint water, double tile, postfx::ReflectedLanding landing) {
  postfx::FrameDesc f;
  f.depth = {g.depth(), GL_DEPTH_COMPONENT32F};
  f.normal = {g.normal(), g.normalFormat()};
  f.albedo = {g.albedo(), GL_RGBA16F};
  f.target = {g.target(), GL_RGBA32F};
  f.camera.position = glm::dvec3(0.0, cameraY, 0.0);
  f.camera.view = glm::mat4(s.view);
  f.camera.projection = s.projection;
  f.sun.direction = towardSun();
  f.sun.irradiance = kSunIrradiance;
  f.water.level = 0.0;
  f.water.texture = {water, GL_RGBA32F};
  f.water.cascadeCount = 1;
  f.water.tileSize[0] = tile;
  f.water.ior = kIor;
  f.reflectedCaustics.gridResolution = 256;
  f.reflectedCaustics.windowSize = 24.0f;
  f.reflectedCaustics.landing = landing;
  return f;
}

std::vector<glm::vec4> readTarget(const SyntheticGbuffer& g) {
  return postfxtest::readRgba(g.target(), kWidth, kHeight);
}

float flatReflectance() {
  return postfx::shared::fresnelReflectance(static_cast<float>(towardSun().y), kIor);
}

// A scene, its G-buffer, water and frame: one dispatch's worth.
struct Receivers {
  double cameraY;
  SyntheticScene scene;
  SyntheticGbuffer gbuffer;
  OwnedTexture water;
  postfx::FrameDesc frame;
  Receivers(const glm::dvec3& look, double y, double amplitude,
            postfx::ReflectedLanding landing = postfx::ReflectedLanding::HeightLayers)
      : cameraY(y),
        scene(receiverScene(look, y)),
        gbuffer(scene),
        water(postfxtest::makeCrossingWaves(256, 8.0, amplitude)),
        frame(frameFor(gbuffer, scene, y, water, 8.0, landing)) {}
};

const glm::dvec3 kLookAtPier{0.0, 0.25, -1.0};

// The contracts both landings keep (ReflectedCausticsSettings::landing).
class PostfxReflectedLandingTest : public PostfxReflectedCausticsTest,
                                   public ::testing::WithParamInterface<postfx::ReflectedLanding> {
 protected:
  bool onDepth() const { return GetParam() == postfx::ReflectedLanding::ViewDepth; }
};

INSTANTIATE_TEST_SUITE_P(Landings, PostfxReflectedLandingTest,
                         ::testing::Values(postfx::ReflectedLanding::ViewDepth,
                                           postfx::ReflectedLanding::HeightLayers),
                         [](const ::testing::TestParamInfo<postfx::ReflectedLanding>& info) {
                           return info.param == postfx::ReflectedLanding::ViewDepth
                                      ? std::string("ViewDepth")
                                      : std::string("HeightLayers");
                         });

TEST_P(PostfxReflectedLandingTest, FlatWaterMirrorsExactlyTheFresnelShareOfTheSun) {
  Receivers s(kLookAtPier, 0.6, 0.0, GetParam());
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const std::vector<glm::vec4> out = readTarget(s.gbuffer);
  const float r = flatReflectance();
  ASSERT_GT(r, 0.01f);
  int ceiling = 0, wall = 0, dark = 0, edge = 0, rippled = 0;
  // On the view's depth each pixel gets what the grid's triangles landed on it: exact (to float
  // rounding) where whole triangles cover it; where the sub-pixel ones are summed as points
  // their sums ripple with the grid's beat against the pixels (under 5 %, and 1 % for all but a
  // few), and so where a broken triangle's corner shares reach (a few pixels from an edge).
  // Near the water's edge at a wall's foot (four grid cells' rise, tan(elevation) per metre of
  // run, and two pixels) part of the light comes from triangles the foot breaks (their rays
  // from behind the wall go nowhere), and within two pixels of another surface's edge or the
  // frame's from triangles broken across the two or cut by the frame: their corners' shares are
  // spread over a pixel or two, so there the light is only bounded, and the frame's flux kept.
  const double cell = double(s.frame.reflectedCaustics.windowSize) /
                      double(s.frame.reflectedCaustics.gridResolution);
  const glm::dvec3 sun = towardSun();
  const double cellRise = cell * sun.y / glm::length(glm::dvec2(sun.x, sun.z));
  const double radiansPerPixel = glm::radians(70.0) / kHeight;
  auto besideAnEdge = [&s](int x, int y) {
    if (x < 2 || y < 2 || x >= kWidth - 2 || y >= kHeight - 2) return true;  // the frame's
    const int surface = s.gbuffer.pixel(x, y).surface;
    for (int j = std::max(y - 2, 0); j <= std::min(y + 2, kHeight - 1); ++j)
      for (int i = std::max(x - 2, 0); i <= std::min(x + 2, kWidth - 1); ++i)
        if (s.gbuffer.pixel(i, j).surface != surface) return true;
    return false;
  };
  double landed = 0.0, flat = 0.0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const auto& p = s.gbuffer.pixel(x, y);
      const glm::vec4 light = out[static_cast<std::size_t>(y) * kWidth + x];
      const double height = p.position.y + s.cameraY;
      const double facing = glm::dot(p.normal, mirrorReversed());
      if (p.surface >= 0 && height > 0.01 && facing > 0.0) {
        const double foot = 4.0 * cellRise + 2.0 * glm::length(p.position) * radiansPerPixel;
        const bool bounded = onDepth() && (height < foot || besideAnEdge(x, y));
        for (int c = 0; c < 3; ++c) {
          const double expected = double(kAlbedo * kSunIrradiance[c] * r) * facing;
          if (bounded) {
            ASSERT_GE(light[c], 0.0f);
            ASSERT_LE(light[c], 1.5 * expected) << x << "," << y;
          } else {
            ASSERT_NEAR(light[c], expected, (onDepth() ? 5e-2 : 2e-3) * expected)
                << x << "," << y << " surface " << p.surface;
            if (c == 0 && std::abs(light[c] - expected) > 1e-2 * expected) ++rippled;
          }
        }
        edge += bounded ? 1 : 0;
        landed += double(light[0]);
        flat += double(kAlbedo * kSunIrradiance[0] * r) * facing;
        (p.surface == kCeiling ? ceiling : wall) += 1;
      } else if (p.surface < 0 || height < -0.01 || facing < 0.0) {
        // The sky, under the water, facing up or away: nothing at all.
        ASSERT_EQ(light, glm::vec4(0.0f)) << x << "," << y << " surface " << p.surface;
        ++dark;
      }
      EXPECT_EQ(light.a, 0.0f);
    }
  EXPECT_GT(ceiling, 400);
  EXPECT_GT(wall, 200);
  EXPECT_GT(dark, 400);
  // The bounded pixels are a band, the frame's light flat water's (measured 0.980: the foot's
  // broken triangles lose what their hidden rays carried).
  EXPECT_LT(edge, (ceiling + wall) / 4);
  EXPECT_LT(rippled, (ceiling + wall) / 20) << "more than 5 % of the pixels off by over 1 %";
  EXPECT_NEAR(landed / flat, 1.0, 0.03);
}

TEST_P(PostfxReflectedLandingTest, WavesKeepTheMeanAndDrawAPattern) {
  Receivers flat(kLookAtPier, 0.6, 0.0, GetParam()), waves(kLookAtPier, 0.6, 0.02, GetParam());
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  ASSERT_EQ(postfx::dispatch(*fx, flat.frame), postfx::Result::Ok);
  ASSERT_EQ(postfx::dispatch(*fx, waves.frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const std::vector<glm::vec4> a = readTarget(flat.gbuffer), b = readTarget(waves.gbuffer);
  double sumFlat = 0.0, sumWaves = 0.0, sumSquares = 0.0;
  int n = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      ASSERT_TRUE(std::isfinite(b[i].r) && b[i].r >= 0.0f) << x << "," << y;
      if (waves.gbuffer.pixel(x, y).surface != kCeiling) {
        if (a[i].r == 0.0f) {
          ASSERT_EQ(b[i].r, 0.0f) << "light where flat water gives none";
        }
        continue;
      }
      const double ratio = double(b[i].r / a[i].r);
      sumFlat += double(a[i].r);
      sumWaves += double(b[i].r);
      sumSquares += ratio * ratio;
      ++n;
    }
  ASSERT_GT(n, 400);
  // The ceiling's view is a few metres of water's light: its mean is flat water's within the
  // pattern's sampling (a few bright lines more or less).
  EXPECT_NEAR(sumWaves / sumFlat, 1.0, 0.15);
  const double meanRatio = sumWaves / sumFlat;
  const double contrast = std::sqrt(std::max(sumSquares / n - meanRatio * meanRatio, 0.0));
  EXPECT_GT(contrast, 0.2) << "the waves' mirrored network is missing";
}

// Mean of a field layer's level 0 over the window's inner half (the grid reaches beyond the
// window on every side: light mirrored or refracted in from outside lands there too).
double innerMean(GLuint texture, int layer) {
  GLint side = 0;
  glGetTextureLevelParameteriv(texture, 0, GL_TEXTURE_WIDTH, &side);
  std::vector<float> texels(static_cast<std::size_t>(side) * side);
  glGetTextureSubImage(texture, 0, 0, 0, layer, side, side, 1, GL_RED, GL_FLOAT,
                       static_cast<GLsizei>(texels.size() * sizeof(float)), texels.data());
  double sum = 0.0;
  int n = 0;
  for (int y = side / 4; y < 3 * side / 4; ++y)
    for (int x = side / 4; x < 3 * side / 4; ++x) {
      sum += double(texels[static_cast<std::size_t>(y) * side + x]);
      ++n;
    }
  return sum / n;
}

TEST_F(PostfxReflectedCausticsTest, ReflectedAndTransmittedFluxAddUpToTheIncidentFlux) {
  // The same waves mirrored onto the first height layer and refracted onto the first depth
  // layer (the wavefront area ratio's window), each relative to flat water's share: weighted by
  // R_flat and T_flat they carry all the light that reached the water. Steep waves (slopes to
  // ~0.39, 21 degrees) spread R far from R_flat; the sun 50 degrees up mirrors none of it back
  // into the water (below 2 x 21 degrees the steepest faces would, and their light would meet
  // the next wave, which neither field follows).
  Receivers s(kLookAtPier, 0.6, 0.05);
  s.frame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  s.frame.caustics.tileUnresolvedSpread = false;
  s.frame.sun.angularDiameterDegrees = 0.0f;
  s.frame.sun.direction =
      glm::dvec3(0.0, std::sin(glm::radians(50.0)), std::cos(glm::radians(50.0)));
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics | postfx::Feature::Caustics |
                                    postfx::Feature::WavefrontAreaRatio);
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const double reflected = innerMean(fx->reflected.field().texture(), 0);
  const double transmitted = innerMean(fx->wavefrontAreaRatio.texture(), 0);
  const float cosine = static_cast<float>(glm::normalize(s.frame.sun.direction).y);
  const double r = postfx::shared::fresnelReflectance(cosine, kIor);
  const double t = postfx::shared::fresnelTransmittance(cosine, kIor);
  EXPECT_NEAR(r + t, 1.0, 1e-6);
  EXPECT_GT(std::abs(reflected - 1.0), 0.01) << "the waves should move R away from flat water's";
  // Measured 1.0002 (reflected 1.033 x R 0.0245, transmitted 0.9994 x T 0.9755).
  EXPECT_NEAR(r * reflected + t * transmitted, 1.0, 2e-3)
      << "reflected " << reflected << " x R " << r << ", transmitted " << transmitted << " x T "
      << t;
}

TEST_P(PostfxReflectedLandingTest, FeatureOffOrDisabledChangesNothingBitForBit) {
  Receivers s(kLookAtPier, 0.6, 0.02, GetParam());
  s.frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  auto run = [&s](postfx::Feature features, bool enabled) {
    const glm::vec4 zero(0.0f);
    glClearTexImage(s.gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
    auto fx = postfxtest::makeContext(features);
    s.frame.reflectedCaustics.enabled = enabled;
    EXPECT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    return readTarget(s.gbuffer);
  };
  const std::vector<glm::vec4> without = run(postfx::Feature::Caustics, true);
  const std::vector<glm::vec4> disabled =
      run(postfx::Feature::Caustics | postfx::Feature::ReflectedCaustics, false);
  const std::vector<glm::vec4> with =
      run(postfx::Feature::Caustics | postfx::Feature::ReflectedCaustics, true);
  ASSERT_EQ(std::memcmp(without.data(), disabled.data(), without.size() * sizeof(glm::vec4)), 0);
  int added = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      const auto& p = s.gbuffer.pixel(x, y);
      if (p.surface < 0 || p.position.y + s.cameraY <= 0.0) {
        // Under the water and on the sky: the seabed light alone, to the bit.
        ASSERT_EQ(std::memcmp(&with[i], &without[i], sizeof(glm::vec4)), 0) << x << "," << y;
      } else if (with[i].r > without[i].r) {
        ++added;
      }
    }
  EXPECT_GT(added, 400);
}

TEST_P(PostfxReflectedLandingTest, SkippedWithNothingAboveTheWaterInView) {
  // A diver's camera 2 m down looking down at the seabed: no part of the frustum reaches the
  // level, so the pass records nothing and reports 0 ms.
  Receivers s(glm::dvec3(0.0, -1.0, -0.2), -2.0, 0.02, GetParam());
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  for (int frame = 0; frame < 6; ++frame)
    ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok);
  const postfx::PassStats stats = postfx::stats(*fx).pass(postfx::Pass::ReflectedCaustics);
  EXPECT_TRUE(stats.present);
  EXPECT_TRUE(stats.skipped);
  EXPECT_EQ(stats.lastMs, 0.0);
  EXPECT_EQ(fx->reflected.allocatedBytes(), 0u) << "a skipped pass holds no memory";
  // Seen from above, it runs and is timed; the estimate is what GL holds.
  Receivers above(kLookAtPier, 0.6, 0.02, GetParam());
  for (int frame = 0; frame < 6; ++frame)
    ASSERT_EQ(postfx::dispatch(*fx, above.frame), postfx::Result::Ok);
  const postfx::PassStats ran = postfx::stats(*fx).pass(postfx::Pass::ReflectedCaustics);
  EXPECT_FALSE(ran.skipped);
  EXPECT_GT(ran.lastMs, 0.0);
  postfx::detail::FramePlan plan = postfx::detail::planFrame(*fx, above.frame);
  ASSERT_TRUE(plan.reflected);
  EXPECT_EQ(postfx::detail::frameMemoryBytes(fx->desc, above.frame, kWidth, kHeight, plan),
            fx->reflected.allocatedBytes());
}

TEST_P(PostfxReflectedLandingTest, BadSettingsAreRefusedWithNothingDrawn) {
  Receivers s(kLookAtPier, 0.6, 0.02, GetParam());
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  const glm::vec4 marker(0.25f, 0.5f, 0.75f, 1.0f);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  struct Case {
    const char* field;
    void (*spoil)(postfx::ReflectedCausticsSettings&, float);
  };
  const Case cases[] = {
      {"intensity", [](postfx::ReflectedCausticsSettings& r, float v) { r.intensity = v; }},
      {"windowSize", [](postfx::ReflectedCausticsSettings& r, float v) { r.windowSize = v; }},
      {"maxHeight", [](postfx::ReflectedCausticsSettings& r, float v) { r.maxHeight = v; }},
      {"maxIrradiance", [](postfx::ReflectedCausticsSettings& r, float v) { r.maxIrradiance = v; }},
      {"gridResolution",
       [](postfx::ReflectedCausticsSettings& r, float) { r.gridResolution = 4096; }},
      {"heightLayers", [](postfx::ReflectedCausticsSettings& r, float) { r.heightLayers = 0; }}};
  for (const Case& c : cases)
    for (float bad : {nan, -1.0f, 1e30f}) {
      s.gbuffer.target();
      glClearTexImage(s.gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &marker[0]);
      postfx::FrameDesc frame = s.frame;
      c.spoil(frame.reflectedCaustics, bad);
      ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::InvalidArgument)
          << c.field << " " << bad;
      EXPECT_NE(std::string(postfx::lastError(fx.get()))
                    .find(std::string("reflectedCaustics.") + c.field),
                std::string::npos)
          << postfx::lastError(fx.get());
      for (const glm::vec4& v : readTarget(s.gbuffer)) ASSERT_EQ(v, marker);
    }
  // A frame that needs the water but gives none is refused too.
  postfx::FrameDesc frame = s.frame;
  frame.water.texture = {};
  EXPECT_NE(postfx::dispatch(*fx, frame), postfx::Result::Ok);
}

TEST_P(PostfxReflectedLandingTest, WaterInTheShadeMirrorsNothing) {
  // A sun shadow map whose left half (light-space x < 0) is occluded: a pier's shade on the
  // water. A receiver whose flat mirror ray comes from shaded water gets nothing (the field
  // holds the shade: its grid points read the map); one lit from sunlit water gets exactly what
  // it gets without the mask.
  Receivers s(kLookAtPier, 0.6, 0.0, GetParam());
  const int side = 256;
  GLuint map = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &map);
  OwnedTexture owned(map);
  glTextureStorage2D(map, 1, GL_DEPTH_COMPONENT32F, side, side);
  std::vector<float> depths(static_cast<std::size_t>(side) * side);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x)
      depths[static_cast<std::size_t>(y) * side + x] = x < side / 2 ? 0.0f : 1.0f;
  glTextureSubImage2D(map, 0, 0, 0, side, side, GL_DEPTH_COMPONENT, GL_FLOAT, depths.data());
  const glm::dmat4 lightClip =
      glm::orthoRH_ZO(-30.0, 30.0, -30.0, 30.0, 1.0, 300.0) *
      glm::lookAt(100.0 * towardSun(), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  s.frame.shadow.depth = {map, GL_DEPTH_COMPONENT32F};
  s.frame.shadow.worldToLightClip = lightClip;
  s.frame.shadow.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  auto plain = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  ASSERT_EQ(postfx::dispatch(*plain, s.frame), postfx::Result::Ok);
  const std::vector<glm::vec4> unmasked = readTarget(s.gbuffer);
  const glm::vec4 zero(0.0f);
  glClearTexImage(s.gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
  auto fx =
      postfxtest::makeContext(postfx::Feature::ReflectedCaustics | postfx::Feature::ShadowMask);
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const std::vector<glm::vec4> masked = readTarget(s.gbuffer);
  int shaded = 0, sunlit = 0;
  const glm::dvec3 lr = mirrorReversed();
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      if (!(unmasked[i].r > 0.0f)) {
        ASSERT_EQ(masked[i], zero);
        continue;
      }
      const auto& p = s.gbuffer.pixel(x, y);
      const glm::dvec3 world = p.position + glm::dvec3(0.0, s.cameraY, 0.0);
      const glm::dvec3 water = world + lr * (world.y / -lr.y);
      const glm::dvec4 clip = lightClip * glm::dvec4(water, 1.0);
      const double u = 0.5 * (clip.x / clip.w) + 0.5;
      if (u < 0.5 - 16.0 / side) {
        ASSERT_EQ(masked[i], zero) << x << "," << y;
        ++shaded;
      } else if (u < 0.5 - 4.0 / side) {
        // Within 4 m of the shade's edge the field's lookup, filtered over the pixel's
        // footprint, may reach a little past it (measured: under 0.1 %).
        ASSERT_LE(masked[i].r, 0.01f * unmasked[i].r) << x << "," << y;
        ++shaded;
      } else if (u > 0.5 + 16.0 / side) {
        ASSERT_NEAR(masked[i].r, unmasked[i].r, 1e-6f * unmasked[i].r) << x << "," << y;
        ++sunlit;
      } else if (u > 0.5 + 4.0 / side) {
        ASSERT_NEAR(masked[i].r, unmasked[i].r, 0.01f * unmasked[i].r) << x << "," << y;
      }
    }
  EXPECT_GT(shaded, 100);
  EXPECT_GT(sunlit, 100);
}

TEST_P(PostfxReflectedLandingTest, EachViewDrawsWhatAContextOfItsOwnWould) {
  // Two cameras 7 m apart in one dispatch: each view's field follows its own camera, so each
  // image is bit for bit what a context drawing that camera alone draws.
  Receivers a(kLookAtPier, 0.6, 0.02, GetParam()),
      b(glm::dvec3(0.3, 0.1, -1.0), 1.2, 0.02, GetParam());
  b.frame.camera.position = glm::dvec3(7.0, 1.2, 3.0);
  b.frame.water.texture = a.frame.water.texture;
  std::vector<glm::vec4> alone[2];
  Receivers* both[2] = {&a, &b};
  for (int v = 0; v < 2; ++v) {
    auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
    ASSERT_EQ(postfx::dispatch(*fx, both[v]->frame), postfx::Result::Ok);
    alone[v] = readTarget(both[v]->gbuffer);
    const glm::vec4 zero(0.0f);
    glClearTexImage(both[v]->gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
  }
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  postfx::View* views[2] = {nullptr, nullptr};
  postfx::ViewDesc descs[2];
  for (int v = 0; v < 2; ++v) {
    ASSERT_EQ(postfx::createView(*fx, views[v]), postfx::Result::Ok);
    const postfx::FrameDesc& f = both[v]->frame;
    descs[v] = {views[v], f.depth, f.normal, f.albedo, f.target, f.camera, {}, nullptr};
  }
  EXPECT_EQ(postfx::dispatch(*fx, a.frame, descs, 2), postfx::Result::Ok)
      << postfx::lastError(fx.get());
  for (int v = 0; v < 2; ++v) {
    const std::vector<glm::vec4> together = readTarget(both[v]->gbuffer);
    EXPECT_EQ(std::memcmp(together.data(), alone[v].data(), together.size() * sizeof(glm::vec4)), 0)
        << "view " << v;
    EXPECT_FALSE(postfx::stats(*views[v]).pass(postfx::Pass::ReflectedCaustics).skipped);
    postfx::destroyView(*fx, views[v]);
  }
}

TEST_P(PostfxReflectedLandingTest, EveryHostStateSurvivesDispatch) {
  // The host's unusual state (postfx_host_state.h) around a frame whose reflected pass runs with
  // its field's spread and the shadow mask, one it skips, and one it refuses.
  Receivers s(kLookAtPier, 0.6, 0.02, GetParam());
  GLuint map = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &map);
  OwnedTexture owned(map);
  glTextureStorage2D(map, 1, GL_DEPTH_COMPONENT32F, 64, 64);
  const float one = 1.0f;
  glClearTexImage(map, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);
  s.frame.shadow.depth = {map, GL_DEPTH_COMPONENT32F};
  s.frame.shadow.worldToLightClip =
      glm::orthoRH_ZO(-30.0, 30.0, -30.0, 30.0, 1.0, 300.0) *
      glm::lookAt(100.0 * towardSun(), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  s.frame.shadow.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics |
                                    postfx::Feature::ShadowMask | postfx::Feature::Caustics);
  postfxtest::HostState host;
  host.set();
  const postfxtest::GlSnapshot before = postfxtest::snapshotGlState();
  auto expectSame = [&before](const char* when) {
    const postfxtest::GlSnapshot after = postfxtest::snapshotGlState();
    for (const auto& [name, value] : before)
      EXPECT_EQ(value, after.at(name)) << when << ": " << name;
  };
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  expectSame("pass ran");
  s.frame.reflectedCaustics.enabled = false;
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok);
  expectSame("pass skipped");
  s.frame.reflectedCaustics.enabled = true;
  s.frame.reflectedCaustics.maxHeight = -1.0f;
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::InvalidArgument);
  expectSame("dispatch refused");
  host.reset();
}

// A stiff or extreme input: what it changes in the pier scene's frame.
struct ExtremeCase {
  const char* name;
  double amplitude;  // of the waves (m); 0.3 gives slopes past 2
  void (*apply)(postfx::FrameDesc&);
};

// Every extreme case: finite light, never negative, never above the clamp's brightest mirror
// light (albedo E R maxIrradiance; R of the grazing sun near 1), nothing under the water; and a
// step of 1e-4 rad in the sun's elevation moves the image by little (no jump, no blow-up).
TEST_P(PostfxReflectedLandingTest, ExtremeInputsStayFiniteBoundedAndContinuous) {
  const ExtremeCase cases[] = {
      {"grazing sun 0.2 deg", 0.02,
       [](postfx::FrameDesc& f) {
         f.sun.direction =
             glm::dvec3(0.0, std::sin(glm::radians(0.2)), std::cos(glm::radians(0.2)));
       }},
      {"sun at the zenith", 0.02,
       [](postfx::FrameDesc& f) {
         f.sun.direction = {0.0, 1.0, 0.0};
       }},
      {"steep waves (slopes past 2)", 0.3, [](postfx::FrameDesc&) {}},
      {"camera 1e6 m from the origin", 0.02,
       [](postfx::FrameDesc& f) {
         f.camera.position += glm::dvec3(1e6, 0.0, -1e6);
         f.water.level = 0.0;
       }},
      {"window 1 m, grid 64", 0.02,
       [](postfx::FrameDesc& f) {
         f.reflectedCaustics.windowSize = 1.0f;
         f.reflectedCaustics.gridResolution = 64;
       }},
      {"window 1e4 m", 0.02, [](postfx::FrameDesc& f) { f.reflectedCaustics.windowSize = 1e4f; }},
      {"maxHeight 1 cm", 0.02, [](postfx::FrameDesc& f) { f.reflectedCaustics.maxHeight = 0.01f; }},
      {"maxHeight 1e4 m, one layer", 0.02,
       [](postfx::FrameDesc& f) {
         f.reflectedCaustics.maxHeight = 1e4f;
         f.reflectedCaustics.heightLayers = 1;
       }},
      {"ior 1 (no mirror)", 0.02, [](postfx::FrameDesc& f) { f.water.ior = 1.0f; }},
      {"ior 3", 0.02, [](postfx::FrameDesc& f) { f.water.ior = 3.0f; }},
      {"clamp 1, modulation only", 0.05,
       [](postfx::FrameDesc& f) {
         f.reflectedCaustics.maxIrradiance = 1.0f;
         f.reflectedCaustics.includeMirrorMean = false;
       }},
      {"point sun, no unresolved spread", 0.05,
       [](postfx::FrameDesc& f) {
         f.sun.angularDiameterDegrees = 0.0f;
         f.caustics.tileUnresolvedSpread = false;
       }},
  };
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  for (const ExtremeCase& c : cases) {
    SCOPED_TRACE(c.name);
    Receivers s(kLookAtPier, 0.6, c.amplitude, GetParam());
    c.apply(s.frame);
    auto render = [&s, &fx](const postfx::FrameDesc& frame) {
      const glm::vec4 zero(0.0f);
      glClearTexImage(s.gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
      EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
      return readTarget(s.gbuffer);
    };
    const std::vector<glm::vec4> a = render(s.frame);
    // Two steps of the sun's elevation: the change must be small, and shrink with the step (a
    // jump does not).
    for (const double step : {1e-4, 1e-6}) {
      postfx::FrameDesc stepped = s.frame;
      const glm::dvec3 sun = glm::normalize(stepped.sun.direction);
      const double elevation = std::asin(sun.y) - step, azimuth = std::atan2(sun.x, sun.z);
      stepped.sun.direction =
          glm::dvec3(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                     std::cos(elevation) * std::cos(azimuth));
      const std::vector<glm::vec4> b = render(stepped);
      const float r = std::max(
          postfx::shared::fresnelReflectance(float(sun.y), s.frame.water.ior),
          postfx::shared::fresnelReflectance(float(std::sin(elevation)), s.frame.water.ior));
      const float bound =
          kAlbedo * kSunIrradiance.r * r * s.frame.reflectedCaustics.maxIrradiance * 1.001f + 1e-6f;
      double sumA = 0.0, sumDiff = 0.0;
      for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
          const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
          const auto& p = s.gbuffer.pixel(x, y);
          for (const glm::vec4* v : {&a[i], &b[i]}) {
            ASSERT_TRUE(std::isfinite(v->r) && std::isfinite(v->g) && std::isfinite(v->b))
                << x << "," << y;
            if (s.frame.reflectedCaustics.includeMirrorMean) {
              ASSERT_GE(v->r, 0.0f);
            }
            ASSERT_LE(std::abs(v->r), bound) << x << "," << y;
            if (p.surface < 0 || p.position.y + s.cameraY <= 0.0) {
              ASSERT_EQ(*v, glm::vec4(0.0f));
            }
          }
          // The flat mirror light here: the scale the change is measured against.
          const glm::dvec3 lr(sun.x, -sun.y, sun.z);
          if (p.surface >= 0 && p.position.y + s.cameraY > 0.0)
            sumA += double(kAlbedo * kSunIrradiance.r * r) * std::max(glm::dot(p.normal, lr), 0.0);
          sumDiff += double(std::abs(a[i].r - b[i].r));
        }
      // The flat mean alone moves by dR/de ~ 1e-4 relative; the network moves by a 1e-4 rad turn
      // of every ray (under a millimetre at these heights, a cell is 9 cm): a per-mille change of
      // the mirror light where the layers filter it. On the view's depth the lines are as sharp as
      // the grid draws them, each pixel centre lit by one triangle: under a point sun with no
      // spread, the turn moves every line edge past some centres (measured 1.7 %, 0.06 % for a
      // 1e-5 step, 0.003 % for 1e-6: continuous). 1e-6 must move it 50 times less than 1e-4 may.
      const double allowed = step > 1e-5 ? (onDepth() ? 0.02 : 0.01) : 2e-4;
      if (sumA > 0.0) {
        EXPECT_LT(sumDiff / sumA, allowed)
            << "sun step " << step << " changed the image by " << sumDiff / sumA;
      }
    }
  }
}

// A deterministic fuzz of what the pass reads: its settings, the sun, the water (level, IOR,
// texels) and the camera, one or two wild values a case (NaN, infinities, bounds and past them,
// far magnitudes). Every case is refused with the target untouched, or drawn finite with
// nothing under the water; no GL error either way.
TEST_P(PostfxReflectedLandingTest, FuzzedFramesAreRefusedCleanlyOrDrawnFinite) {
  using postfxfuzz::wild;
  using postfxfuzz::wildFloat;
  using postfxfuzz::wildInt;
  Receivers s(kLookAtPier, 0.6, 0.02, GetParam());
  s.frame.reflectedCaustics.gridResolution = 64;  // fast: the fuzz is about values, not detail
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics | postfx::Feature::Caustics);
  postfxfuzz::Rng rng(32);
  const glm::vec4 marker(0.125f, 0.25f, 0.375f, 1.0f);
  int drawn = 0, refused = 0;
  for (int n = 0; n < 240; ++n) {
    postfx::FrameDesc f = s.frame;
    postfx::ReflectedCausticsSettings& r = f.reflectedCaustics;
    for (int e = 0, edits = 1 + rng.below(2); e < edits; ++e) {
      switch (rng.below(12)) {
        case 0:
          r.intensity = wildFloat(rng, r.intensity);
          break;
        case 1:
          r.windowSize = wildFloat(rng, r.windowSize);
          break;
        case 2:
          r.gridResolution = wildInt(rng, r.gridResolution);
          break;
        case 3:
          r.heightLayers = wildInt(rng, r.heightLayers);
          break;
        case 4:
          r.maxHeight = wildFloat(rng, r.maxHeight);
          break;
        case 5:
          r.maxIrradiance = wildFloat(rng, r.maxIrradiance);
          break;
        case 6:
          f.sun.direction[rng.below(3)] = wild(rng, f.sun.direction.y);
          break;
        case 7:
          f.water.level = wild(rng, f.water.level);
          break;
        case 8:
          f.water.ior = wildFloat(rng, f.water.ior);
          break;
        case 9:
          f.camera.position[rng.below(3)] = wild(rng, f.camera.position.y);
          break;
        case 10:
          f.water.tileSize[0] = wild(rng, f.water.tileSize[0]);
          break;
        default:
          f.sun.angularDiameterDegrees = wildFloat(rng, f.sun.angularDiameterDegrees);
      }
    }
    glClearTexImage(s.gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &marker[0]);
    const postfx::Result result = postfx::dispatch(*fx, f);
    expectNoGlErrors("fuzzed dispatch");
    const std::vector<glm::vec4> out = readTarget(s.gbuffer);
    if (result != postfx::Result::Ok) {
      ++refused;
      for (const glm::vec4& v : out) ASSERT_EQ(v, marker) << "case " << n << " refused but drew";
      continue;
    }
    ++drawn;
    for (std::size_t i = 0; i < out.size(); ++i) {
      const glm::vec4& v = out[i];
      ASSERT_TRUE(std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b)) << "case " << n;
      ASSERT_EQ(v.a, marker.a) << "case " << n << ": alpha written";
    }
  }
  EXPECT_GT(drawn, 40);
  EXPECT_GT(refused, 40);
}

TEST_P(PostfxReflectedLandingTest, PatternLiesWhereTheMirrorPutsIt) {
  // A single gentle wave along x (2 m long, 1 mm high) under a sun with an x component: to first
  // order the ceiling 2 m up is lit by I = 1 - H div(J s) at the water point its flat mirror ray
  // left from, w = p - rise H, i.e. 1 + H J_xx A k^2 sin(k w.x + phase). The plugin's light
  // divided by flat water's must follow that, phase and all.
  const double tile = 8.0, amplitude = 0.001, k = 2.0 * 3.141592653589793 / 2.0, phase = 0.4;
  const int size = 256;
  std::vector<glm::vec4> texels(static_cast<std::size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const double x = (i + 0.5) * tile / size, a = k * x + phase;
      texels[static_cast<std::size_t>(j) * size + i] =
          glm::vec4(float(amplitude * k * std::cos(a)), 0.0f, float(amplitude * std::sin(a)), 1.0f);
    }
  OwnedTexture water(postfxtest::makeWaterTextureFromTexels(size, texels));
  Receivers s(kLookAtPier, 0.6, 0.0, GetParam());
  const glm::dvec3 sun = glm::normalize(glm::dvec3(0.45, 0.7, 0.55));
  s.frame.sun.direction = sun;
  s.frame.sun.angularDiameterDegrees = 0.0f;
  s.frame.caustics.tileUnresolvedSpread = false;
  s.frame.reflectedCaustics.gridResolution = 1024;
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok);
  const std::vector<glm::vec4> flat = readTarget(s.gbuffer);
  const glm::vec4 zero(0.0f);
  glClearTexImage(s.gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
  s.frame.water.texture = {water, GL_RGBA32F};
  ASSERT_EQ(postfx::dispatch(*fx, s.frame), postfx::Result::Ok);
  const std::vector<glm::vec4> waves = readTarget(s.gbuffer);
  const glm::dvec4 j = postfx::detail::reflectedLandingJacobian(sun);
  const glm::dvec2 rise = -glm::dvec2(sun.x, sun.z) / sun.y;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  int n = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) {
      const auto& p = s.gbuffer.pixel(x, y);
      const std::size_t i = static_cast<std::size_t>(y) * kWidth + x;
      if (p.surface != kCeiling || !(flat[i].r > 0.0f)) continue;
      const glm::dvec3 world = p.position + glm::dvec3(0.0, s.cameraY, 0.0);
      const double h = world.y;
      const glm::dvec2 w = glm::dvec2(world.x, world.z) - rise * h;
      const double predicted = h * j.x * amplitude * k * k * std::sin(k * w.x + phase);
      const double measured = double(waves[i].r / flat[i].r) - 1.0;
      sxy += predicted * measured;
      sxx += predicted * predicted;
      syy += measured * measured;
      ++n;
    }
  ASSERT_GT(n, 400);
  const double correlation = sxy / std::sqrt(sxx * syy);
  // Measured: correlation 0.996, gain 0.94 (the grid low-passes the wave a little); on the
  // view's depth 0.925 (the ceiling's far half takes its sub-pixel triangles as points, whose
  // sums ripple by about a per cent with the grid's beat against the pixels: the 8 % pattern
  // of this millimetre wave shows it).
  EXPECT_GT(correlation, onDepth() ? 0.9 : 0.95);
  EXPECT_NEAR(sxy / sxx, 1.0, 0.15);
}

TEST(ReflectedCausticsMath, MirrorTurnsTheLandingByTwiceTheSlope) {
  // Sun from +z at elevation e: a slope dh/dz = s tilts the normal by s toward -z, turning the
  // mirrored ray's elevation by 2 s; its landing per metre of height, -cot(elevation) along z,
  // moves by 2 / sin^2(e) per unit slope; across the azimuth a slope dh/dx = s gives the ray
  // 2 s sin(e) sideways per sin(e) of rise: 2 per unit slope at any elevation.
  for (double degrees : {10.0, 35.0, 70.0}) {
    const double e = glm::radians(degrees);
    const glm::dvec3 sun(0.0, std::sin(e), std::cos(e));
    const glm::dvec4 j = postfx::detail::reflectedLandingJacobian(sun);
    // Packed (d offset / d sx, d offset / d sz): the along-azimuth term is d(offset.z) / d sz.
    EXPECT_NEAR(std::abs(j.w), 2.0 / (std::sin(e) * std::sin(e)), 1e-4 * (1.0 + std::abs(j.w)))
        << degrees;
    EXPECT_NEAR(std::abs(j.x), 2.0, 1e-4) << degrees;
    EXPECT_NEAR(j.y, 0.0, 1e-6);
    EXPECT_NEAR(j.z, 0.0, 1e-6);
    // A flat mirror keeps the disc's angular size: its landing spread per metre of height is the
    // refraction-free one, r^2 / 4 (1 / sin^4 along, 1 / sin^2 across).
    const double r = 0.01;
    const glm::dvec3 c = postfx::detail::reflectedSunDiscCovariance(sun, r);
    const double s2 = std::sin(e) * std::sin(e);
    EXPECT_NEAR(c.z, 0.25 * r * r / (s2 * s2), 1e-3 * c.z) << degrees;
    EXPECT_NEAR(c.x, 0.25 * r * r / s2, 1e-3 * c.x) << degrees;
  }
}

}  // namespace

namespace {

TEST(ReflectedCausticsMath, ReceiverLightIsWhatItsRaysDeliver) {
  using namespace postfx::shared;
  const glm::vec3 sun = glm::normalize(glm::vec3(0.3f, 0.35f, 0.9f));
  const glm::vec3 toWater(sun.x, -sun.y, sun.z);  // l_r
  const glm::vec2 rise = -glm::vec2(sun.x, sun.z) / sun.y;
  // An underside, a face tilted down toward the water, a wall leaning back a little: each faces
  // the mirrored sun (the pass lights no other).
  const glm::vec3 normals[] = {{0, -1, 0},
                               glm::normalize(glm::vec3(-0.2f, -0.3f, 0.9f)),
                               glm::normalize(glm::vec3(0.4f, 0.1f, 0.8f))};
  for (const glm::vec3& n : normals) {
    ASSERT_GT(glm::dot(n, toWater), 0.0f);
    // Flat water (D = I rise): I times flat water's n . l_r, whatever the face.
    for (float i : {1.0f, 0.3f, 2.5f}) {
      const glm::vec3 field(i, i * rise.x, i * rise.y);
      EXPECT_NEAR(reflectedReceiverLight(n, field, sun.y, rise, 0.0f, 32.0f),
                  i * std::max(glm::dot(n, toWater), 0.0f), 1e-5f);
      EXPECT_NEAR(reflectedReceiverLight(n, field, sun.y, rise, 1.0f, 32.0f),
                  (i - 1.0f) * glm::dot(n, toWater), 1e-5f);
    }
    // Two bundles of rays, each of horizontal flux f and drift d, deliver f (-n.y - n.xz . d)
    // per unit area each (a ray's flux times its cosine on the face over its own on the
    // horizontal), summed.
    const glm::vec2 d1(0.1f, -1.2f), d2(-0.5f, -3.0f);
    const float f1 = 0.7f, f2 = 0.4f;
    auto onFace = [&](float f, glm::vec2 d) {
      const glm::vec3 ray = glm::normalize(glm::vec3(d.x, 1.0f, d.y));
      return f * std::max(-glm::dot(n, ray), 0.0f) / ray.y;
    };
    const glm::vec3 field(f1 + f2, f1 * d1.x + f2 * d2.x, f1 * d1.y + f2 * d2.y);
    ASSERT_GT(onFace(1.0f, d1), 0.0f);  // both bundles meet the face from the front
    ASSERT_GT(onFace(1.0f, d2), 0.0f);
    EXPECT_NEAR(reflectedReceiverLight(n, field, sun.y, rise, 0.0f, 32.0f) / sun.y,
                onFace(f1, d1) + onFace(f2, d2), 1e-4f);
  }
  // An underside weights every ray alike; a wall facing the sea the low ones more.
  const glm::vec3 low(1.0f, 1.0f * rise.x * 2.0f, 1.0f * rise.y * 2.0f);
  const glm::vec3 flat(1.0f, rise.x, rise.y);
  const glm::vec3 underside(0, -1, 0), wall = glm::normalize(glm::vec3(sun.x, 0.0f, sun.z));
  EXPECT_FLOAT_EQ(reflectedReceiverLight(underside, low, sun.y, rise, 0.0f, 32.0f),
                  reflectedReceiverLight(underside, flat, sun.y, rise, 0.0f, 32.0f));
  EXPECT_NEAR(reflectedReceiverLight(wall, low, sun.y, rise, 0.0f, 32.0f),
              2.0f * reflectedReceiverLight(wall, flat, sun.y, rise, 0.0f, 32.0f), 1e-5f);
  // Rays from behind a face: nothing, never negative light.
  EXPECT_EQ(reflectedReceiverLight(-wall, flat, sun.y, rise, 0.0f, 32.0f), 0.0f);
  // The clamp bounds what a face gathers (from low rays more than the horizontal carries), and
  // the modulation is that light less flat water's.
  const glm::vec3 grazing(1.0f, 40.0f * rise.x, 40.0f * rise.y);
  EXPECT_FLOAT_EQ(reflectedReceiverLight(wall, grazing, sun.y, rise, 0.0f, 5.0f), 5.0f);
  EXPECT_FLOAT_EQ(reflectedReceiverLight(wall, grazing, sun.y, rise, 1.0f, 5.0f),
                  5.0f - reflectedReceiverLight(wall, flat, sun.y, rise, 0.0f, 5.0f));
}

TEST(ReflectedCausticsMath, MeanDriftAndEscapeHaveTheirLimits) {
  using namespace postfx::shared;
  const glm::vec2 rise(0.4f, -2.5f);
  // The mean drift where light arrives; flat water's where almost none does (noise).
  EXPECT_NEAR(reflectedMeanDrift(glm::vec3(2.0f, 1.0f, -3.0f), rise).x, 0.5f, 1e-6f);
  EXPECT_NEAR(reflectedMeanDrift(glm::vec3(2.0f, 1.0f, -3.0f), rise).y, -1.5f, 1e-6f);
  EXPECT_EQ(reflectedMeanDrift(glm::vec3(0.0f, 0.0f, 0.0f), rise), rise);
  EXPECT_EQ(reflectedMeanDrift(glm::vec3(1e-3f, 5.0f, 5.0f), rise), rise);
  // Masking: flat water and steep rays escape whole; grazing rays do not; never above 1.
  for (float e : {5.0f, 20.0f, 60.0f, 89.0f}) {
    const float s = std::sin(glm::radians(e));
    EXPECT_FLOAT_EQ(reflectedEscape(1.0f, s, s), 1.0f) << e;
  }
  EXPECT_FLOAT_EQ(reflectedEscape(0.98f, 0.6f, 0.8f), 1.0f);
  EXPECT_NEAR(reflectedEscape(0.98f, 0.02f, 0.3f), 2.0f * 0.98f * 0.02f / 0.3f, 1e-6f);
  EXPECT_EQ(reflectedEscape(0.98f, 0.0f, 0.3f), 0.0f);
  EXPECT_TRUE(std::isfinite(reflectedEscape(1.0f, 0.5f, 0.0f)));
}

}  // namespace
