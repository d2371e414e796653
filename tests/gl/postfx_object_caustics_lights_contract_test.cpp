// Local lights' contracts: bad input is refused naming the field, with nothing drawn
// and the host's GL state untouched; the light count is bounded by CreateDesc::maxLocalLights;
// sunCaustics = false leaves the sun out.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_object_caustics_lights_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

class PostfxObjectCausticsLightsContractTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  HostState host_;
};

TEST_F(PostfxObjectCausticsLightsContractTest, CreateDescBoundsTheLightCount) {
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::ObjectCaustics;
  postfx::Context* fx = nullptr;
  for (int bad : {-1, postfx::kMaxLocalLightsLimit + 1, 1 << 30}) {
    desc.maxLocalLights = bad;
    EXPECT_EQ(postfx::create(desc, fx), Result::InvalidArgument) << bad;
    EXPECT_EQ(fx, nullptr);
    EXPECT_NE(std::string(postfx::lastError(nullptr)).find("CreateDesc.maxLocalLights"),
              std::string::npos)
        << postfx::lastError(nullptr);
  }
  for (int good : {0, 1, postfx::kMaxLocalLightsLimit}) {
    desc.maxLocalLights = good;
    ASSERT_EQ(postfx::create(desc, fx), Result::Ok) << postfx::lastError(nullptr);
    postfx::destroy(fx);
    fx = nullptr;
  }
}

TEST_F(PostfxObjectCausticsLightsContractTest, BadLightsFailCleanly) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  auto fx = makeLightContext(3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* name;
    Result expected;
    const char* mentions;
    std::function<void(std::vector<postfx::LocalLight>&, postfx::FrameDesc&)> spoil;
  };
  using Lights = std::vector<postfx::LocalLight>;
  using Frame = postfx::FrameDesc;
  const Case cases[] = {
      {"more lights than created for", Result::InvalidArgument, "objectCaustics.lightCount",
       [](Lights& l, Frame& f) {
         l.resize(4, l[0]);
         f.objectCaustics.lightCount = 4;
       }},
      {"negative light count", Result::InvalidArgument, "objectCaustics.lightCount",
       [](Lights&, Frame& f) { f.objectCaustics.lightCount = -1; }},
      {"null lights", Result::InvalidArgument, "objectCaustics.lights is null",
       [](Lights&, Frame& f) { f.objectCaustics.lights = nullptr; }},
      {"NaN position", Result::InvalidArgument, "objectCaustics.lights[1].position",
       [nan](Lights& l, Frame&) { l[1].position.y = nan; }},
      {"infinite position", Result::InvalidArgument, "objectCaustics.lights[0].position",
       [inf](Lights& l, Frame&) { l[0].position.x = -inf; }},
      {"position 1e12 m out", Result::InvalidArgument, "objectCaustics.lights[2].position",
       [](Lights& l, Frame&) { l[2].position.z = 1e12; }},
      {"negative range", Result::InvalidArgument, "objectCaustics.lights[2].range",
       [](Lights& l, Frame&) { l[2].range = -1.0; }},
      {"NaN range", Result::InvalidArgument, "objectCaustics.lights[0].range",
       [nan](Lights& l, Frame&) { l[0].range = nan; }},
      {"range past 1e6 m", Result::InvalidArgument, "objectCaustics.lights[0].range",
       [](Lights& l, Frame&) { l[0].range = 2e6; }},
      {"cone angle 0", Result::InvalidArgument, "objectCaustics.lights[2].coneAngleDegrees",
       [](Lights& l, Frame&) { l[2].coneAngleDegrees = 0.0f; }},
      {"cone angle 180", Result::InvalidArgument, "objectCaustics.lights[0].coneAngleDegrees",
       [](Lights& l, Frame&) { l[0].coneAngleDegrees = 180.0f; }},
      {"cone angle negative", Result::InvalidArgument, "objectCaustics.lights[0].coneAngleDegrees",
       [](Lights& l, Frame&) { l[0].coneAngleDegrees = -10.0f; }},
      {"cone angle NaN", Result::InvalidArgument, "objectCaustics.lights[0].coneAngleDegrees",
       [](Lights& l, Frame&) { l[0].coneAngleDegrees = float(NAN); }},
      {"softness above 1", Result::InvalidArgument, "objectCaustics.lights[0].coneSoftness",
       [](Lights& l, Frame&) { l[0].coneSoftness = 1.5f; }},
      {"softness negative", Result::InvalidArgument, "objectCaustics.lights[2].coneSoftness",
       [](Lights& l, Frame&) { l[2].coneSoftness = -0.1f; }},
      {"direction of zero length", Result::InvalidArgument, "objectCaustics.lights[0].direction",
       [](Lights& l, Frame&) { l[0].direction = glm::dvec3(0.0); }},
      {"direction infinite", Result::InvalidArgument, "objectCaustics.lights[2].direction",
       [inf](Lights& l, Frame&) { l[2].direction.x = inf; }},
      {"direction whose square overflows", Result::InvalidArgument,
       "objectCaustics.lights[0].direction",
       [](Lights& l, Frame&) { l[0].direction = glm::dvec3(1e200, 0.0, 0.0); }},
      {"negative intensity", Result::InvalidArgument, "objectCaustics.lights[1].intensity",
       [](Lights& l, Frame&) { l[1].intensity.b = -1.0f; }},
      {"NaN intensity", Result::InvalidArgument, "objectCaustics.lights[0].intensity",
       [](Lights& l, Frame&) { l[0].intensity.r = float(NAN); }},
      {"not a light type", Result::InvalidArgument, "objectCaustics.lights[0].type",
       [](Lights& l, Frame&) { l[0].type = static_cast<postfx::LocalLightType>(7); }},
      {"receivers missing", Result::MissingTexture, "objectCaustics.lights[1].receivers.depth",
       [](Lights& l, Frame&) { l[1].receivers.depth.texture = 0; }},
      {"receivers not a depth format", Result::UnsupportedFormat,
       "objectCaustics.lights[0].receivers.depth",
       [&host](Lights& l, Frame&) {
         l[0].receivers.depth = {host.scene.target, 0};
       }},
      {"receiver matrix NaN", Result::InvalidArgument,
       "objectCaustics.lights[2].receivers.worldToLightClip",
       [nan](Lights& l, Frame&) { l[2].receivers.worldToLightClip[1][1] = nan; }},
      {"receiver bias negative", Result::InvalidArgument, "objectCaustics.lights[0].receivers.bias",
       [](Lights& l, Frame&) { l[0].receivers.bias = -1.0f; }},
      // Without casters the lights are still checked: the contract does not hang on the scene.
      {"bad light, no casters", Result::InvalidArgument, "objectCaustics.lights[0].range",
       [](Lights& l, Frame& f) {
         f.objectCaustics.casterCount = 0;
         l[0].range = -5.0;
       }},
  };
  host.scene.clearTarget(glm::vec4(0.5f));
  for (const Case& c : cases) {
    const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.5, 0.0}), {});
    Lights lights(3);
    for (postfx::LocalLight& light : lights) {
      light.position = {0.0, 4.0, 0.0};
      light.receivers = host.receivers.desc();
    }
    lights[1].type = postfx::LocalLightType::Point;
    lights[1].direction = glm::dvec3(0.0);  // ignored for a point light
    postfx::ObjectCausticsSettings small;   // the valid frame draws: keep it cheap
    small.gridSize = 32;
    small.mapSize = 64;
    postfx::FrameDesc frame = host.frame(&caster, 1, small);
    frame.objectCaustics.lights = lights.data();
    frame.objectCaustics.lightCount = 3;
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    host.scene.clearTarget(glm::vec4(0.5f));
    c.spoil(lights, frame);
    if (frame.objectCaustics.lights != nullptr) frame.objectCaustics.lights = lights.data();
    host_.set();
    const GlSnapshot before = snapshotGlState();
    const Result r = postfx::dispatch(*fx, frame);
    const std::string message = postfx::lastError(fx.get());
    std::printf("%-34s -> %s: %s\n", c.name, postfx::toString(r), message.c_str());
    EXPECT_EQ(r, c.expected) << c.name;
    EXPECT_NE(message.find(c.mentions), std::string::npos) << c.name << ": " << message;
    for (const auto& [name, value] : before)
      EXPECT_EQ(value, snapshotGlState().at(name)) << c.name << ": GL state '" << name << "'";
    host_.reset();
    for (const glm::vec4& v :
         readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
      ASSERT_EQ(v, glm::vec4(0.5f)) << c.name << ": nothing drawn";
  }
}

// A context created without lights refuses any; the sun's receivers are optional once the sun
// is left out, and the sun's pass is then skipped.
TEST_F(PostfxObjectCausticsLightsContractTest, SunCausticsOffLeavesTheSunOut) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.5, 0.0}), {});
  postfx::LocalLight light;
  light.receivers = host.receivers.desc();

  auto none = makeLightContext(0);
  postfx::FrameDesc frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
  frame.objectCaustics.lights = &light;
  frame.objectCaustics.lightCount = 1;
  EXPECT_EQ(postfx::dispatch(*none, frame), Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(none.get())).find("CreateDesc.maxLocalLights"),
            std::string::npos);

  auto fx = makeLightContext(1);
  frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
  frame.objectCaustics.sunCaustics = false;
  frame.objectCaustics.receivers = {};  // not read without the sun
  host.scene.clearTarget(glm::vec4(0.25f));
  for (int i = 0; i < 6; ++i) ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << i;
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok);
  const postfx::PassStats& p = postfx::stats(*fx).pass(postfx::Pass::ObjectCaustics);
  EXPECT_TRUE(p.skipped);
  EXPECT_EQ(p.lastMs, 0.0);
  for (const glm::vec4& v :
       readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
    ASSERT_EQ(v, glm::vec4(0.25f)) << "no sun caustic";

  // The sun back on, its receivers required again.
  frame.objectCaustics.sunCaustics = true;
  EXPECT_EQ(postfx::dispatch(*fx, frame), Result::MissingTexture);
  EXPECT_NE(std::string(postfx::lastError(fx.get())).find("objectCaustics.receivers.depth"),
            std::string::npos)
      << postfx::lastError(fx.get());
}

}  // namespace
