// The plugin's reflected caustics against the traced reference on waves: a pier's underside and
// a quay wall above a few crossing waves under a low sun, each pattern (light over flat water's)
// correlated pixel by pixel, for both landings (ReflectedCausticsSettings::landing). Small scenes
// with nothing else in them, so that a disagreement is the model's, not the harbour's geometry or
// shadows.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"
#include "gbuffer_readback.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "synthetic_gbuffer.h"
#include "water_readback.h"

namespace {

using namespace ocean::reference;
using ocean::validation::SyntheticGbuffer;
using ocean::validation::SyntheticScene;
using ocean::validation::SyntheticSurface;

class ReferenceReflectedPatternTest : public testsupport::GlTest {};

constexpr int kWidth = 128, kHeight = 80;
constexpr double kCameraY = 0.6;
constexpr double kTile = 8.0;

enum class Receiver { Underside, Wall };

// Camera 0.6 m up at the origin. Underside: a pier deck's underside 2 m up over z in [-7, 0],
// seen looking up; wall: a quay wall at z = -9 facing +z up to 5 m.
SyntheticScene scene(Receiver r) {
  SyntheticScene s;
  s.width = kWidth;
  s.height = kHeight;
  const glm::dvec3 look =
      r == Receiver::Underside ? glm::dvec3(0.0, 0.35, -1.0) : glm::dvec3(0.0, 0.15, -1.0);
  s.view =
      glm::dmat4(glm::lookAt(glm::dvec3(0.0), glm::normalize(look), glm::dvec3(0.0, 1.0, 0.0)));
  s.projection = postfxtest::reverseZPerspective(60.0, double(kWidth) / kHeight, 0.05, 200.0);
  s.albedoFormat = GL_RGBA16F;
  s.targetFormat = GL_RGBA32F;
  s.maxDistance = 199.0;
  SyntheticSurface surface;
  if (r == Receiver::Underside) {
    surface.point = {0.0, 2.0 - kCameraY, 0.0};
    surface.normal = {0.0, -1.0, 0.0};
    surface.keep = {0.0, 0.0, 1.0, 7.0};  // z >= -7
  } else {
    surface.point = {0.0, 0.0, -9.0};
    surface.normal = {0.0, 0.0, 1.0};
    surface.keep = {0.0, -1.0, 0.0, 5.0 - kCameraY};  // y <= 5 m
  }
  surface.albedo = glm::vec3(0.5f);
  SyntheticSurface seabed;
  seabed.point = {0.0, -3.0 - kCameraY, 0.0};
  seabed.albedo = glm::vec3(0.5f);
  s.surfaces = {surface, seabed};
  return s;
}

TriangleMesh quad(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                  const glm::dvec3& d, const glm::dvec3& normal) {
  TriangleMesh m;
  m.positions = {a, b, c, d};
  m.normals.assign(4, normal);
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

struct Correlation {
  double correlation = 0.0, pluginMean = 0.0, tracedMean = 0.0;
  size_t pixels = 0;
};

Correlation comparePatterns(Receiver r, const glm::dvec3& sun, double amplitude, int grid,
                            postfx::ReflectedLanding landing) {
  const SyntheticScene s = scene(r);
  const SyntheticGbuffer gbuffer(s);
  const GLuint flatWater = postfxtest::makeWaterTexture(32, 1, 0.0);
  const GLuint waves = postfxtest::makeCrossingWaves(512, kTile, amplitude);
  auto fx = postfxtest::makeContext(postfx::Feature::ReflectedCaustics);
  postfx::FrameDesc frame;
  frame.depth = {gbuffer.depth(), GL_DEPTH_COMPONENT32F};
  frame.normal = {gbuffer.normal(), gbuffer.normalFormat()};
  frame.albedo = {gbuffer.albedo(), GL_RGBA16F};
  frame.target = {gbuffer.target(), GL_RGBA32F};
  frame.camera.position = glm::dvec3(0.0, kCameraY, 0.0);
  frame.camera.view = glm::mat4(s.view);
  frame.camera.projection = s.projection;
  frame.sun.direction = sun;
  frame.sun.irradiance = glm::vec3(1.0f);
  frame.water.level = 0.0;
  frame.water.texture = {flatWater, GL_RGBA32F};
  frame.water.cascadeCount = 1;
  frame.water.tileSize[0] = float(kTile);
  frame.water.ior = 1.333f;
  frame.reflectedCaustics.gridResolution = grid;
  // The underside between the two highest layers (1.74 and 2.5 m); the wall's 5 m under eight
  // layers to 4 m (their top fade reaching to 6 m).
  frame.reflectedCaustics.maxHeight = r == Receiver::Underside ? 2.5f : 4.0f;
  frame.reflectedCaustics.heightLayers = r == Receiver::Underside ? 6 : 8;
  frame.reflectedCaustics.landing = landing;
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto flat = postfxtest::readRgba(gbuffer.target(), kWidth, kHeight);
  const glm::vec4 zero(0.0f);
  glClearTexImage(gbuffer.target(), 0, GL_RGBA, GL_FLOAT, &zero[0]);
  frame.water.texture = {waves, GL_RGBA32F};
  EXPECT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
  const auto lit = postfxtest::readRgba(gbuffer.target(), kWidth, kHeight);

  postfx::CreateDesc create;
  GBufferCopy copy;
  std::string error;
  EXPECT_TRUE(readGBuffer(create, frame, copy, error)) << error;
  const FrameReceivers receivers = receiversOf(frame, copy);
  WaterTextureSurface surface;
  EXPECT_TRUE(surface.read(frame.water, error)) << error;
  const TriangleMesh receiver =
      r == Receiver::Underside
          ? quad({-300, 2, -7}, {300, 2, -7}, {300, 2, 0}, {-300, 2, 0}, {0, -1, 0})
          : quad({-300, -3, -9}, {300, -3, -9}, {300, 5, -9}, {-300, 5, -9}, {0, 0, 1});
  const TriangleMesh seabed =
      quad({-300, -3, -300}, {-300, -3, 300}, {300, -3, 300}, {300, -3, -300}, {0, 1, 0});
  const auto embree = EmbreeScene::create({receiver, seabed}, frame.camera.position, error);
  EXPECT_TRUE(embree) << error;
  FrameTraceDesc desc;
  desc.towardSun = sun;
  desc.ior = frame.water.ior;
  desc.sunAngularRadius = glm::radians(0.5 * double(frame.sun.angularDiameterDegrees));
  desc.reflected = true;
  desc.maxBatches = 12;
  const FrameTraceResult traced = traceFrameCaustics(surface, *embree, receivers, desc);

  double sp = 0, st = 0, spp = 0, stt = 0, spt = 0;
  Correlation c;
  for (size_t i = 0; i < receivers.size(); ++i) {
    if (!traced.reflectedLit[i] || !(flat[i].r > 0.0f)) continue;
    const double p = double(lit[i].r) / double(flat[i].r);
    const double t = traced.reflectedIrradiance[i] / traced.flatReflected[i];
    sp += p;
    st += t;
    spp += p * p;
    stt += t * t;
    spt += p * t;
    ++c.pixels;
  }
  const double n = double(c.pixels);
  c.pluginMean = sp / n;
  c.tracedMean = st / n;
  c.correlation =
      (spt / n - c.pluginMean * c.tracedMean) /
      std::sqrt((spp / n - c.pluginMean * c.pluginMean) * (stt / n - c.tracedMean * c.tracedMean));
  glDeleteTextures(1, &flatWater);
  glDeleteTextures(1, &waves);
  std::printf(
      "%s %s amplitude %.3f grid %d: %zu pixels, correlation %.3f, mean %.3f vs traced %.3f "
      "(noise p99 %.3f)\n",
      r == Receiver::Underside ? "underside" : "wall",
      landing == postfx::ReflectedLanding::ViewDepth ? "view depth" : "height layers", amplitude,
      grid, c.pixels, c.correlation, c.pluginMean, c.tracedMean, traced.reflectedNoiseQuantile);
  return c;
}

glm::dvec3 lowSun() {
  const double e = glm::radians(20.0), a = glm::radians(20.0);
  return glm::dvec3(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
}

constexpr postfx::ReflectedLanding kLayers = postfx::ReflectedLanding::HeightLayers;
constexpr postfx::ReflectedLanding kDepth = postfx::ReflectedLanding::ViewDepth;

// Measured (128x80, grid 512): gentle waves (slopes ~0.03) 0.956, mean 0.943 against the
// trace's 0.966; waves with slopes ~0.1 (the harbour's) 0.828, 0.998 against 0.991. Between
// layers the pattern is interpolated: with a layer at the underside's height it reads 0.925.
TEST_F(ReferenceReflectedPatternTest, UndersideAgreesWithTheTrace) {
  const Correlation gentle = comparePatterns(Receiver::Underside, lowSun(), 0.005, 512, kLayers);
  EXPECT_GT(gentle.correlation, 0.93);
  EXPECT_NEAR(gentle.pluginMean / gentle.tracedMean, 1.0, 0.035);
  const Correlation steeper = comparePatterns(Receiver::Underside, lowSun(), 0.02, 512, kLayers);
  EXPECT_GT(steeper.correlation, 0.78);
  EXPECT_NEAR(steeper.pluginMean / steeper.tracedMean, 1.0, 0.035);
}

// A wall weights the low rays more than an underside does (reflectedReceiverLight): with the
// harbour's slopes its mean is 1.078 of flat water's in the trace; weighted as if every ray
// came along flat water's mirror ray it read 0.999, with the field's drift sums 1.075.
// Correlation 0.977 and 0.946 (eight layers to 4 m); 0.940 and 0.918 with the lookup filtered
// for the wall's own footprint (not stretched along the mirror ray), 0.84 for the steeper waves
// with six layers to 6 m.
TEST_F(ReferenceReflectedPatternTest, WallAgreesWithTheTrace) {
  const Correlation gentle = comparePatterns(Receiver::Wall, lowSun(), 0.005, 512, kLayers);
  EXPECT_GT(gentle.correlation, 0.95);
  EXPECT_NEAR(gentle.pluginMean / gentle.tracedMean, 1.0, 0.03);
  const Correlation steeper = comparePatterns(Receiver::Wall, lowSun(), 0.02, 512, kLayers);
  EXPECT_GT(steeper.correlation, 0.92);
  EXPECT_NEAR(steeper.pluginMean / steeper.tracedMean, 1.0, 0.03);
}

// Landing on the view's depth there is nothing between layers to approximate: each pixel gets
// the rays that land on it. Measured (128x80, grid 512): underside 0.975 / 0.937 (gentle /
// steeper; the layers' 0.956 / 0.828), means 0.959 / 0.996 against 0.966 / 0.991; wall 0.934 /
// 0.934, means 0.998 / 1.098 against 0.998 / 1.078 (the wall's sub-pixel triangles are summed
// as points: a little noisier than the layers' filtered lookup, 0.977 / 0.946).
TEST_F(ReferenceReflectedPatternTest, ViewDepthAgreesWithTheTrace) {
  const Correlation underside[2] = {
      comparePatterns(Receiver::Underside, lowSun(), 0.005, 512, kDepth),
      comparePatterns(Receiver::Underside, lowSun(), 0.02, 512, kDepth)};
  EXPECT_GT(underside[0].correlation, 0.95);
  EXPECT_GT(underside[1].correlation, 0.91);
  const Correlation wall[2] = {comparePatterns(Receiver::Wall, lowSun(), 0.005, 512, kDepth),
                               comparePatterns(Receiver::Wall, lowSun(), 0.02, 512, kDepth)};
  EXPECT_GT(wall[0].correlation, 0.91);
  EXPECT_GT(wall[1].correlation, 0.91);
  for (const Correlation& c : {underside[0], underside[1], wall[0], wall[1]})
    EXPECT_NEAR(c.pluginMean / c.tracedMean, 1.0, 0.03);
}

}  // namespace
