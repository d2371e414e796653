// A host with glass but no water simulation: the object caustics need no water texture, only
// the passes that sample it (seabed caustics, god rays) do; and the benchmark floor runs beside
// the object caustics alone, adding exactly nothing, so that their cost has a floor ratio too.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cstdio>
#include <string>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Feature;
using postfx::Result;

class PostfxObjectCausticsHostTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  HostState host_;
};

postfx::CasterMesh glassCaster(const GlMesh& mesh) {
  postfx::CasterMaterial glass;
  glass.ior = 1.5f;
  return mesh.caster(translation({0.2, 1.5, 0.1}), glass);
}

void expectSameState(const GlSnapshot& before, const GlSnapshot& after, const std::string& when) {
  for (const auto& [name, value] : before) {
    auto it = after.find(name);
    ASSERT_NE(it, after.end()) << name;
    EXPECT_EQ(value, it->second) << when << ": GL state '" << name << "' changed";
  }
}

TEST_F(PostfxObjectCausticsHostTest, GlassWithoutWaterRunsWithItsFloor) {
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 48, 24);
  const postfx::CasterMesh caster = glassCaster(mesh);
  postfx::FrameDesc frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
  frame.water.texture = {};  // no water simulation at all
  const int w = host.scene.spec().width, h = host.scene.spec().height;
  const glm::vec4 background(0.25f);

  // Without the floor: the light the object caustics add.
  auto plain = makeObjectContext();
  host.scene.clearTarget(background);
  ASSERT_EQ(postfx::dispatch(*plain, frame), Result::Ok) << postfx::lastError(plain.get());
  const std::vector<glm::vec4> reference = readRgba(host.scene.target, w, h);
  int lit = 0;
  for (const glm::vec4& v : reference) lit += v.g > background.g + 1e-3f ? 1 : 0;

  // With it: same host state before and after every frame, the floor timed, the same image.
  auto timed = makeObjectContext(postfx::testing::BenchmarkFloor);
  ASSERT_TRUE(postfx::stats(*timed).pass(postfx::Pass::Floor).present);
  ASSERT_TRUE(postfx::stats(*timed).pass(postfx::Pass::ObjectCaustics).present);
  host_.set();
  const GlSnapshot before = snapshotGlState();
  for (int i = 0; i < 6; ++i) {
    ASSERT_EQ(postfx::dispatch(*timed, frame), Result::Ok) << postfx::lastError(timed.get());
    expectSameState(before, snapshotGlState(), "object caustics with the floor, no water");
  }
  host_.reset();
  glFinish();
  host.scene.clearTarget(background);
  ASSERT_EQ(postfx::dispatch(*timed, frame), Result::Ok) << postfx::lastError(timed.get());
  const std::vector<glm::vec4> withFloor = readRgba(host.scene.target, w, h);
  const postfx::PassStats& f = postfx::stats(*timed).pass(postfx::Pass::Floor);
  const postfx::PassStats& o = postfx::stats(*timed).pass(postfx::Pass::ObjectCaustics);
  int differing = 0;
  for (size_t i = 0; i < reference.size(); ++i) differing += withFloor[i] != reference[i] ? 1 : 0;
  std::printf(
      "no water: %d of %zu pixels lit; floor skipped %d median %.3f ms; object caustics skipped "
      "%d median %.3f ms (ratio %.2f); pixels differing with the floor %d\n",
      lit, reference.size(), int(f.skipped), f.medianMs, int(o.skipped), o.medianMs,
      f.medianMs > 0.0 ? o.medianMs / f.medianMs : 0.0, differing);
  EXPECT_GT(lit, 0) << "the caustic must reach the image for the comparison to mean anything";
  EXPECT_FALSE(f.skipped);
  EXPECT_GT(f.medianMs, 0.0);
  EXPECT_FALSE(o.skipped);
  EXPECT_GT(o.medianMs, 0.0);
  EXPECT_EQ(differing, 0) << "the floor adds exactly 0";
  EXPECT_NE(postfx::objectCausticMap(*timed).texture, 0u);
}

TEST_F(PostfxObjectCausticsHostTest, WaterTextureIsRequiredOnlyWhereItIsSampled) {
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  const postfx::CasterMesh caster = glassCaster(mesh);
  GLuint notTexture = 0;
  glGenTextures(1, &notTexture);  // a name, never a texture
  struct Case {
    const char* name;
    Feature features;
    bool causticsEnabled, godRaysEnabled;
    GLuint water;
    Result expected;
  };
  const Feature all = Feature::ObjectCaustics | Feature::Caustics | Feature::GodRays;
  const Case cases[] = {
      {"objects only, no water", Feature::ObjectCaustics, true, true, 0, Result::Ok},
      {"objects only, floor, no water", Feature::ObjectCaustics | postfx::testing::BenchmarkFloor,
       true, true, 0, Result::Ok},
      {"all, caustics and god rays off", all, false, false, 0, Result::Ok},
      {"all, caustics on, no water", all, true, false, 0, Result::MissingTexture},
      {"all, god rays on, no water", all, false, true, 0, Result::MissingTexture},
      {"objects only, stale water name", Feature::ObjectCaustics, true, true, notTexture,
       Result::MissingTexture},
  };
  const glm::vec4 background(0.5f);
  for (const Case& c : cases) {
    auto fx = makeContext(c.features);
    ASSERT_NE(fx, nullptr) << c.name;
    postfx::FrameDesc frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
    frame.water.texture = {c.water, 0};
    frame.caustics.enabled = c.causticsEnabled;
    frame.godRays.enabled = c.godRaysEnabled;
    host.scene.clearTarget(background);
    host_.set();
    const GlSnapshot before = snapshotGlState();
    const Result r = postfx::dispatch(*fx, frame);
    const std::string message = postfx::lastError(fx.get());
    expectSameState(before, snapshotGlState(), c.name);
    host_.reset();
    bool drawn = false;
    for (const glm::vec4& v :
         readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
      drawn = drawn || v != background;
    std::printf("%-32s -> %s: %s; map %u, drawn %d\n", c.name, postfx::toString(r), message.c_str(),
                postfx::objectCausticMap(*fx).texture, int(drawn));
    EXPECT_EQ(r, c.expected) << c.name << ": " << message;
    if (c.expected == Result::Ok) {
      EXPECT_NE(postfx::objectCausticMap(*fx).texture, 0u) << c.name;
      EXPECT_TRUE(drawn) << c.name;
    } else {
      EXPECT_NE(message.find("water"), std::string::npos) << c.name << ": " << message;
      EXPECT_EQ(postfx::objectCausticMap(*fx).texture, 0u) << c.name;
      EXPECT_FALSE(drawn) << c.name << ": nothing drawn";
    }
  }
  glDeleteTextures(1, &notTexture);
}

}  // namespace
