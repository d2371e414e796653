// Local lights' object caustics at the edges: a light that reaches no
// caster costs nothing and allocates nothing; the extreme cases (light inside the caster, on the
// receiver, 1e6 m from the origin, cone 179 degrees, range 0 and 1e6 m, intensity 0 and 1e6, at
// and above the water surface) stay finite and bounded; the host's GL state survives.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <string>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_object_caustics_lights_util.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::LightSkip;
using postfx::Result;

// GL texture names alive in the context (names are handed out in order from 1).
int liveTextures() {
  int count = 0;
  for (GLuint name = 1; name < 4096; ++name) count += glIsTexture(name) == GL_TRUE ? 1 : 0;
  return count;
}

const char* skipName(LightSkip skip) {
  switch (skip) {
    case LightSkip::None:
      return "ran";
    case LightSkip::NoCasterInReach:
      return "no caster in reach";
    case LightSkip::InsideCaster:
      return "inside a caster";
    case LightSkip::AcrossWaterSurface:
      return "across the water surface";
    case LightSkip::CastersAround:
      return "casters around it";
  }
  return "?";
}

class PostfxObjectCausticsLightsStabilityTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  HostState host_;
};

// Lights that cannot reach the caster (too short a range, a cone pointing away, range 0,
// intensity 0) are skipped: 0 ms each, no texture allocated, nothing added. One that reaches it
// runs, is timed and allocates (the test can fail).
TEST_F(PostfxObjectCausticsLightsStabilityTest, UnreachedLightsCostNothing) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(0.5, 32, 16);
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.0, 0.0}), {});
  const glm::dvec3 position(0.0, 3.0, 0.0), down(0.0, -1.0, 0.0);
  LightReceiverMap receivers(position, down, 40.0, 0.0, 256);
  std::vector<postfx::LocalLight> lights(
      4, makeLight(postfx::LocalLightType::Spot, position, down, receivers.desc()));
  lights[0].range = 1.0;                      // the sphere is 1.5 m away
  lights[1].direction = glm::dvec3(0, 1, 0);  // shines up, away from it
  lights[2].range = 0.0;                      // makes no caustics
  lights[3].intensity = glm::vec3(0.0f);      // dark
  lights[3].type = postfx::LocalLightType::Point;
  auto fx = makeLightContext(4);
  const postfx::FrameDesc frame =
      lightsOnlyFrame(host, &caster, 1, lights.data(), 4, sizedSettings(64, 128));
  host.scene.clearTarget(glm::vec4(0.25f));
  const int texturesBefore = liveTextures();
  for (int i = 0; i < 6; ++i) ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
  const postfx::FrameStats& stats = postfx::stats(*fx);
  for (int i = 0; i < 4; ++i) {
    const postfx::PassStats& p = stats.objectLight(i);
    std::printf("light %d: %s, lastMs %.6f medianMs %.6f samples %u\n", i,
                skipName(stats.lightSkip[i]), p.lastMs, p.medianMs, p.samples);
    EXPECT_TRUE(p.present);
    EXPECT_EQ(stats.lightSkip[i], LightSkip::NoCasterInReach) << i;
    EXPECT_TRUE(p.skipped) << i;
    EXPECT_EQ(p.lastMs, 0.0) << i;
    EXPECT_EQ(p.medianMs, 0.0) << i;
  }
  EXPECT_FALSE(stats.objectLight(4).present) << "only the context's 4 light slots are timed";
  EXPECT_EQ(liveTextures(), texturesBefore) << "nothing allocated";
  EXPECT_EQ(postfx::testing::lightCausticMap(*fx).texture, 0u);
  for (const glm::vec4& v :
       readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
    ASSERT_EQ(v, glm::vec4(0.25f)) << "nothing added";

  lights[1].direction = down;  // now it reaches the sphere
  for (int i = 0; i < 6; ++i) ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
  EXPECT_EQ(stats.lightSkip[1], LightSkip::None);
  EXPECT_FALSE(stats.objectLight(1).skipped);
  EXPECT_GT(stats.objectLight(1).lastMs, 0.0);
  EXPECT_TRUE(stats.objectLight(0).skipped);
  EXPECT_GT(liveTextures(), texturesBefore);
  EXPECT_NE(postfx::testing::lightCausticMap(*fx).texture, 0u);
  EXPECT_TRUE(postfx::stats(*fx).pass(postfx::Pass::ObjectCaustics).skipped) << "no sun";
}

TEST_F(PostfxObjectCausticsLightsStabilityTest, HostStateSurvivesTheLights) {
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(0.5, 32, 16);
  const postfx::CasterMesh caster = mesh.caster(translation({0.2, 1.0, 0.1}), {});
  const glm::dvec3 position(0.5, 3.0, 0.0), down(0.0, -1.0, 0.0);
  LightReceiverMap receivers(position, down, 40.0, 0.0, 256);
  const postfx::LocalLight lights[2] = {
      makeLight(postfx::LocalLightType::Spot, position, down, receivers.desc()),
      makeLight(postfx::LocalLightType::Point, position, down, receivers.desc())};
  host_.set();
  const GlSnapshot before = snapshotGlState();
  auto fx = makeLightContext(2);
  postfx::ObjectCausticsSettings s = sizedSettings(64, 128);
  s.temporalFilter = true;
  postfx::FrameDesc frame = host.frame(&caster, 1, s);
  frame.objectCaustics.lights = lights;
  frame.objectCaustics.lightCount = 2;
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    const GlSnapshot after = snapshotGlState();
    for (const auto& [name, value] : before)
      EXPECT_EQ(value, after.at(name)) << "GL state '" << name << "' changed";
  }
  host_.reset();
  EXPECT_EQ(postfx::stats(*fx).lightSkip[0], LightSkip::None);
  EXPECT_EQ(postfx::stats(*fx).lightSkip[1], LightSkip::None);
}

// One extreme case: a frame with one light (and a glass sphere of radius 0.5 at `centre`, the
// receiver plane y = 0), its skip reason, and a map and target that stay finite, non-negative
// and no brighter than the light could make them.
struct Extreme {
  const char* name;
  LightSkip expected;
  std::function<void(postfx::LocalLight&, postfx::FrameDesc&, glm::dvec3& centre)> set;
};

TEST_F(PostfxObjectCausticsLightsStabilityTest, ExtremeCasesStayFinite) {
  const GlMesh mesh = makeSphereMesh(0.5, 48, 24);
  auto fx = makeLightContext(1);
  postfx::ObjectCausticsSettings s = sizedSettings(64, 128);
  s.iterations = 3;
  using Light = postfx::LocalLight;
  using Frame = postfx::FrameDesc;
  using V = glm::dvec3;
  const Extreme cases[] = {
      {"spot 2 m above (baseline)", LightSkip::None, [](Light&, Frame&, V&) {}},
      {"point light inside the caster", LightSkip::InsideCaster,
       [](Light& l, Frame&, V& c) {
         l.type = postfx::LocalLightType::Point;
         l.position = c + V(0.1, 0.0, 0.0);
       }},
      {"light on the receiver, beside the sphere", LightSkip::None,
       [](Light& l, Frame&, V& c) {
         l.position = V(-1.5, 0.0, 0.0);
         l.direction = c - l.position;
       }},
      {"point light touching the sphere", LightSkip::None,
       [](Light& l, Frame&, V& c) {
         l.type = postfx::LocalLightType::Point;
         l.position = c + V(0.0, 0.75, 0.0);
       }},
      {"cone 179 degrees", LightSkip::None,
       [](Light& l, Frame&, V&) { l.coneAngleDegrees = 179.0f; }},
      {"cone 0.01 degrees", LightSkip::None,
       [](Light& l, Frame&, V&) { l.coneAngleDegrees = 0.01f; }},
      {"range 0", LightSkip::NoCasterInReach, [](Light& l, Frame&, V&) { l.range = 0.0; }},
      {"range 1e6 m", LightSkip::None, [](Light& l, Frame&, V&) { l.range = 1e6; }},
      {"intensity 0", LightSkip::NoCasterInReach,
       [](Light& l, Frame&, V&) { l.intensity = glm::vec3(0.0f); }},
      {"intensity 1e6", LightSkip::None,
       [](Light& l, Frame&, V&) { l.intensity = glm::vec3(1e6f); }},
      {"light exactly at the water surface, sphere under water", LightSkip::None,
       [](Light& l, Frame& f, V&) { f.water.level = l.position.y; }},
      {"light above the water shining down into it", LightSkip::AcrossWaterSurface,
       [](Light& l, Frame& f, V&) { f.water.level = l.position.y - 0.5; }},
      {"light and sphere under water", LightSkip::None,
       [](Light& l, Frame& f, V&) { f.water.level = l.position.y + 1.0; }},
      {"sphere resting on the receiver", LightSkip::None, [](Light&, Frame&, V& c) { c.y = 0.5; }},
  };
  for (const Extreme& e : cases) {
    ObjectHost host(sunAt(20.0, 0.0));
    V centre(0.0, 1.0, 0.0);
    Light light = makeLight(postfx::LocalLightType::Spot, V(0.0, 3.0, 0.0), V(0.0, -1.0, 0.0), {});
    postfx::FrameDesc frame = host.frame(nullptr, 1, s);
    e.set(light, frame, centre);
    const double tan = std::min(5.0, 1.0 / std::max(std::abs(light.position.y), 1e-3));
    LightReceiverMap receivers(light.position,
                               light.position.y > 0.05 ? V(0, -1, 0) : V(1, -0.2, 0),
                               glm::degrees(std::atan(tan * 4.0)), 0.0, 256);
    light.receivers = receivers.desc();
    const postfx::CasterMesh caster = mesh.caster(translation(centre), {});
    frame.objectCaustics.casters = &caster;
    frame.objectCaustics.sunCaustics = false;
    frame.objectCaustics.lights = &light;
    frame.objectCaustics.lightCount = 1;
    host.scene.clearTarget(glm::vec4(0.0f));
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok)
        << e.name << ": " << postfx::lastError(fx.get());
    const LightSkip skip = postfx::stats(*fx).lightSkip[0];
    const LightMap map(postfx::testing::lightCausticMap(*fx), light.position);
    double lowest = 0.0;
    for (const glm::dvec3& v : map.value) lowest = std::min({lowest, v.r, v.g, v.b});
    const bool finite = finiteTarget(host);
    std::printf("%-52s %-26s map finite %d lowest %.3g target finite %d\n", e.name, skipName(skip),
                int(map.allFinite()), lowest, int(finite));
    EXPECT_EQ(skip, e.expected) << e.name;
    EXPECT_TRUE(map.allFinite()) << e.name;
    EXPECT_GE(lowest, 0.0) << e.name;
    EXPECT_TRUE(finite) << e.name;
  }
}

// Positions in double: the same light, sphere and receivers 1e6 m from the origin give the
// same map as at the origin.
TEST_F(PostfxObjectCausticsLightsStabilityTest, FarFromTheOriginGivesTheSameMap) {
  const GlMesh mesh = makeSphereMesh(0.5, 64, 32);
  auto fx = makeLightContext(1);
  const postfx::ObjectCausticsSettings s = sizedSettings(128, 256);
  std::vector<glm::dvec3> flux;
  std::vector<double> peaks;
  for (const glm::dvec3 offset : {glm::dvec3(0.0), glm::dvec3(1e6, 0.0, -1e6)}) {
    ObjectHost host(sunAt(20.0, 0.0));
    const glm::dvec3 position = offset + glm::dvec3(0.3, 3.0, 0.0);
    LightReceiverMap receivers(position, glm::dvec3(0, -1, 0), 40.0, 0.0, 512);
    postfx::LocalLight light =
        makeLight(postfx::LocalLightType::Point, position, glm::dvec3(0, -1, 0), receivers.desc());
    const postfx::CasterMesh caster = mesh.caster(translation(offset + glm::dvec3(0, 1, 0)), {});
    postfx::FrameDesc frame = lightsOnlyFrame(host, &caster, 1, &light, 1, s);
    frame.camera.position += offset;
    host.scene.clearTarget(glm::vec4(0.0f));
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    ASSERT_EQ(postfx::stats(*fx).lightSkip[0], LightSkip::None);
    const LightMap map(postfx::testing::lightCausticMap(*fx), light.position);
    ASSERT_TRUE(map.allFinite());
    int x = 0, y = 0;
    peaks.push_back(map.peak(x, y));
    flux.push_back(map.fluxOnPlane(0.0));
    EXPECT_TRUE(finiteTarget(host));
    std::printf("offset %.0e m: flux %.6f, peak %.4f at texel (%d, %d)\n", offset.x, flux.back().g,
                peaks.back(), x, y);
  }
  EXPECT_NEAR(flux[1].g / flux[0].g, 1.0, 0.01);
  EXPECT_NEAR(peaks[1] / peaks[0], 1.0, 0.05);
}

}  // namespace
