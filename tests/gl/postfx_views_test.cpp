// Several views in one dispatch (postfx/views.h): each view's image is bit-identical to a
// context of its own for that camera after the same frames; no view's state leaks into another;
// the view-independent pre-pass runs once per frame whatever the number of views; a refused
// view draws nothing anywhere; split-screen viewports in one target draw what whole targets do;
// a stereo pair sees one world-space pattern; ending a view frees its memory.
#include <gtest/gtest.h>
#include <postfx/testing.h>
#include <postfx/views.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "gl_fixture.h"
#include "god_rays/godrays_constants.h"
#include "postfx_object_caustics_lights_util.h"
#include "postfx_object_caustics_util.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "postfx_views_util.h"

namespace {

using postfxtest::makeFrame;
using postfxtest::makeView;
using postfxtest::Scene;
using postfxtest::SceneSpec;
using postfxtest::viewOf;
using postfxtest::ViewPtr;

class PostfxViewsTest : public testsupport::GlTest {};

constexpr postfx::Feature kSeabed = postfx::Feature::Caustics | postfx::Feature::GodRays |
                                    postfx::testing::RawCausticOutput |
                                    postfx::Feature::WavefrontAreaRatio;

SceneSpec seabedSpec(const glm::dvec3& camera, const glm::dvec3& look) {
  SceneSpec s;
  s.width = 96;
  s.height = 54;
  s.camera = camera;
  s.lookDirection = look;
  s.floorY = -7.0;
  return s;
}

// The seabed frame every test shares: the default tile model, god rays at half resolution.
postfx::FrameDesc seabedFrame(const Scene& scene, GLuint water, postfx::CausticsModel model) {
  postfx::FrameDesc f = makeFrame(scene, water, 3);
  f.caustics.model = model;
  f.caustics.gridResolution = 64;
  f.caustics.tileResolution = 64;
  f.godRays.resolution = postfx::GodRayResolution::Half;
  f.godRays.sampleCount = 12;
  return f;
}

std::vector<glm::vec4> target(const Scene& s) {
  return postfxtest::readRgba(s.target, s.spec().width, s.spec().height);
}

bool identical(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

double added(const std::vector<glm::vec4>& image) {
  double sum = 0.0;
  for (const glm::vec4& p : image) sum += double(p.r) + double(p.g) + double(p.b);
  return sum;
}

// Two cameras over one sea: each frame one context draws both views, two contexts draw one
// each; the water's phase and the cameras move every frame (the god rays' pivot follows them).
void expectViewsMatchOwnContexts(postfx::CausticsModel model) {
  Scene a(seabedSpec({0.0, -2.0, 0.0}, {0.0, -0.6, -1.0}));
  Scene b(seabedSpec({3.0, -1.0, 2.0}, {0.7, -0.5, -0.4}));
  Scene ownA(a.spec()), ownB(b.spec());
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto multi = postfxtest::makeContext(kSeabed);
  auto single0 = postfxtest::makeContext(kSeabed);
  auto single1 = postfxtest::makeContext(kSeabed);
  ViewPtr va = makeView(*multi), vb = makeView(*multi);
  for (int frame = 0; frame < 4; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const glm::dvec3 move(0.37 * frame, 0.0, -0.21 * frame);
    for (const Scene* s : {&a, &b, &ownA, &ownB}) s->clearTarget(glm::vec4(0.0f));
    postfx::FrameDesc shared = seabedFrame(a, water, model);
    shared.water.origin = glm::dvec2(0.11 * frame, 0.05 * frame);
    const postfx::ViewDesc views[] = {viewOf(va.get(), a, move), viewOf(vb.get(), b, -move)};
    ASSERT_EQ(postfx::dispatch(*multi, shared, views, 2), postfx::Result::Ok)
        << postfx::lastError(multi.get());

    postfx::FrameDesc fa = seabedFrame(ownA, water, model), fb = seabedFrame(ownB, water, model);
    fa.water.origin = fb.water.origin = shared.water.origin;
    fa.camera.position += move;
    fb.camera.position -= move;
    ASSERT_EQ(postfx::dispatch(*single0, fa), postfx::Result::Ok);
    ASSERT_EQ(postfx::dispatch(*single1, fb), postfx::Result::Ok);

    EXPECT_GT(added(target(a)), 1.0) << "view A added no light";
    EXPECT_GT(added(target(b)), 1.0) << "view B added no light";
    EXPECT_TRUE(identical(target(a), target(ownA))) << "view A differs from its own context";
    EXPECT_TRUE(identical(target(b), target(ownB))) << "view B differs from its own context";
    const int w = a.spec().width, h = a.spec().height;
    EXPECT_EQ(postfxtest::readRed(postfx::testing::rawCausticTexture(*va), w, h),
              postfxtest::readRed(postfx::testing::rawCausticTexture(*single0), w, h));
    EXPECT_EQ(postfxtest::readRed(postfx::testing::rawCausticTexture(*vb), w, h),
              postfxtest::readRed(postfx::testing::rawCausticTexture(*single1), w, h));
  }
  glDeleteTextures(1, &water);
}

TEST_F(PostfxViewsTest, EachViewIsBitIdenticalToItsOwnContext) {
  expectViewsMatchOwnContexts(postfx::CausticsModel::TileIrradiance);
}

TEST_F(PostfxViewsTest, EachViewIsBitIdenticalToItsOwnContextWithTheWindowModel) {
  // The window follows each view's camera and is recomputed per view into one texture.
  expectViewsMatchOwnContexts(postfx::CausticsModel::WavefrontAreaRatio);
}

// Object caustics: the maps (the sun's with its temporal history, and a spot light's) are drawn
// once and composited into each view; each view still matches a context of its own over frames
// with a moving caster.
TEST_F(PostfxViewsTest, ObjectCausticsSharedMapsMatchOwnContexts) {
  using namespace postfxtest;
  ObjectHost hostA(sunAt(20.0, 30.0));
  SceneSpec other = ObjectHost::defaultSpec();
  other.camera = {3.0, 3.0, 3.0};
  other.lookDirection = {-0.6, -0.7, -0.6};
  ObjectHost hostB(sunAt(20.0, 30.0), 4.0, other);
  ObjectHost ownA(sunAt(20.0, 30.0)), ownB(sunAt(20.0, 30.0), 4.0, other);
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  postfx::ObjectCausticsSettings settings = sizedSettings(128, 256);
  settings.temporalFilter = true;
  const glm::dvec3 lamp(-1.0, 5.0, 0.5), down(0.2, -1.0, 0.0);
  LightReceiverMap lampReceivers(lamp, down, 40.0, 0.0, 512);
  postfx::LocalLight spot =
      makeLight(postfx::LocalLightType::Spot, lamp, down, lampReceivers.desc());
  spot.coneAngleDegrees = 60.0f;
  auto multi = makeLightContext(1), single0 = makeLightContext(1), single1 = makeLightContext(1);
  ViewPtr va = makeView(*multi), vb = makeView(*multi);
  for (int frame = 0; frame < 4; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    const postfx::CasterMesh caster =
        mesh.caster(translation({0.2 + 0.1 * frame, 1.5, 0.1}), postfx::CasterMaterial{});
    for (const ObjectHost* h : {&hostA, &hostB, &ownA, &ownB}) h->scene.clearTarget(glm::vec4(0));
    auto withLight = [&](postfx::FrameDesc f) {
      f.objectCaustics.lights = &spot;
      f.objectCaustics.lightCount = 1;
      return f;
    };
    const postfx::FrameDesc shared = withLight(hostA.frame(&caster, 1, settings));
    const postfx::ViewDesc views[] = {viewOf(va.get(), hostA.scene), viewOf(vb.get(), hostB.scene)};
    ASSERT_EQ(postfx::dispatch(*multi, shared, views, 2), postfx::Result::Ok)
        << postfx::lastError(multi.get());
    ASSERT_EQ(postfx::stats(*multi).lightSkip[0], postfx::LightSkip::None);
    ASSERT_EQ(postfx::dispatch(*single0, withLight(ownA.frame(&caster, 1, settings))),
              postfx::Result::Ok);
    ASSERT_EQ(postfx::dispatch(*single1, withLight(ownB.frame(&caster, 1, settings))),
              postfx::Result::Ok);
    EXPECT_GT(added(target(hostA.scene)), 1.0);
    EXPECT_GT(added(target(hostB.scene)), 1.0);
    EXPECT_TRUE(identical(target(hostA.scene), target(ownA.scene)));
    EXPECT_TRUE(identical(target(hostB.scene), target(ownB.scene)));
  }
}

// Volume caustics in a split screen: the rays are traced once, each view draws them through its
// own camera into its own viewport (their light summed at the view's size, then added at its
// offset); each half matches a context of its own, bit for bit.
TEST_F(PostfxViewsTest, VolumeCausticsSplitScreenHalvesMatchOwnContexts) {
  using namespace postfxtest;
  SceneSpec a = ObjectHost::defaultSpec();
  a.width = 64;
  a.height = 72;
  SceneSpec b = a;
  b.camera = {3.0, 3.0, 3.0};
  b.lookDirection = {-0.6, -0.7, -0.6};
  SceneSpec wide = a;
  wide.width = 128;
  const glm::dvec3 sun = sunAt(20.0, 30.0);
  ObjectHost hostA(sun, 4.0, a), hostB(sun, 4.0, b), split(sun, 4.0, wide);
  for (auto [from, x] : {std::pair{&hostA.scene, 0}, std::pair{&hostB.scene, 64}})
    for (auto [src, dst] :
         {std::pair{from->depth, split.scene.depth}, std::pair{from->normal, split.scene.normal},
          std::pair{from->albedo, split.scene.albedo}})
      glCopyImageSubData(src, GL_TEXTURE_2D, 0, 0, 0, 0, dst, GL_TEXTURE_2D, 0, x, 0, 0, 64, 72, 1);
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  const postfx::CasterMesh caster =
      mesh.caster(translation({0.2, 1.5, 0.1}), postfx::CasterMaterial{});
  postfx::ObjectCausticsSettings settings = sizedSettings(128, 256);
  // The ball and its cone under the water.
  auto underWater = [](postfx::FrameDesc f) {
    f.water.level = 10.0;
    return f;
  };
  const postfx::Feature volume = postfx::Feature::VolumeCaustics;
  auto multi = makeObjectContext(volume), ownA = makeObjectContext(volume),
       ownB = makeObjectContext(volume);
  ViewPtr va = makeView(*multi), vb = makeView(*multi);
  for (const ObjectHost* h : {&hostA, &hostB, &split}) h->scene.clearTarget(glm::vec4(0.0f));
  const postfx::FrameDesc shared = underWater(split.frame(&caster, 1, settings));
  postfx::ViewDesc views[] = {viewOf(va.get(), split.scene), viewOf(vb.get(), split.scene)};
  views[0].camera = viewOf(nullptr, hostA.scene).camera;
  views[1].camera = viewOf(nullptr, hostB.scene).camera;
  views[0].viewport = {0, 0, 64, 72};
  views[1].viewport = {64, 0, 64, 72};
  ASSERT_EQ(postfx::dispatch(*multi, shared, views, 2), postfx::Result::Ok)
      << postfx::lastError(multi.get());
  ASSERT_EQ(postfx::dispatch(*ownA, underWater(hostA.frame(&caster, 1, settings))),
            postfx::Result::Ok)
      << postfx::lastError(ownA.get());
  ASSERT_EQ(postfx::dispatch(*ownB, underWater(hostB.frame(&caster, 1, settings))),
            postfx::Result::Ok);
  const std::vector<glm::vec4> image = target(split.scene), imageA = target(hostA.scene),
                               imageB = target(hostB.scene);
  // Bit for bit, but for light below 1e-30: the object caustic map's farthest splat tails are
  // denormal floats, which llvmpipe's threads flush or keep differently from run to run (seen
  // at 1e-35 .. 1e-40 on the receivers of these views; the volume's own sum is cut at 1e-30).
  auto flushed = [](glm::vec4 p) {
    for (int c = 0; c < 4; ++c)
      if (std::abs(p[c]) < 1e-30f) p[c] = 0.0f;
    return p;
  };
  int differing = 0;
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 64; ++x) {
      differing += flushed(image[size_t(y * 128 + x)]) != flushed(imageA[size_t(y * 64 + x)]);
      differing += flushed(image[size_t(y * 128 + 64 + x)]) != flushed(imageB[size_t(y * 64 + x)]);
    }
  EXPECT_EQ(differing, 0) << "pixels of the split target differ from the whole targets'";
  // The volume drew into both views: without it each view's light is less.
  settings.volume.enabled = false;
  hostA.scene.clearTarget(glm::vec4(0.0f));
  hostB.scene.clearTarget(glm::vec4(0.0f));
  ASSERT_EQ(postfx::dispatch(*ownA, underWater(hostA.frame(&caster, 1, settings))),
            postfx::Result::Ok);
  ASSERT_EQ(postfx::dispatch(*ownB, underWater(hostB.frame(&caster, 1, settings))),
            postfx::Result::Ok);
  EXPECT_GT(added(imageA), added(target(hostA.scene)));
  EXPECT_GT(added(imageB), added(target(hostB.scene)));
}

// A view's image does not change when another view is added, moved far away or removed.
TEST_F(PostfxViewsTest, AnotherViewNeverChangesAView) {
  Scene a(seabedSpec({0.0, -2.0, 0.0}, {0.0, -0.6, -1.0}));
  Scene b(seabedSpec({1.0, -3.0, 1.0}, {0.3, -0.8, -0.5}));
  Scene alone(a.spec());
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto multi = postfxtest::makeContext(kSeabed), single = postfxtest::makeContext(kSeabed);
  ViewPtr va = makeView(*multi), vb = makeView(*multi);
  // Frame by frame, B is absent, present, 1e4 m away (its god-ray pivot jumps), present again.
  const int bCount[] = {0, 1, 1, 0, 1};
  const glm::dvec3 bOffset[] = {{}, {}, {1e4, 0.0, -1e4}, {}, {2.0, 0.0, 0.0}};
  for (int frame = 0; frame < 5; ++frame) {
    SCOPED_TRACE("frame " + std::to_string(frame));
    for (const Scene* s : {&a, &b, &alone}) s->clearTarget(glm::vec4(0.0f));
    postfx::FrameDesc shared = seabedFrame(a, water, postfx::CausticsModel::TileIrradiance);
    shared.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2 + 0.001 * frame));
    const postfx::ViewDesc views[] = {viewOf(va.get(), a), viewOf(vb.get(), b, bOffset[frame])};
    ASSERT_EQ(postfx::dispatch(*multi, shared, views, 1 + bCount[frame]), postfx::Result::Ok)
        << postfx::lastError(multi.get());
    postfx::FrameDesc own = seabedFrame(alone, water, postfx::CausticsModel::TileIrradiance);
    own.sun.direction = shared.sun.direction;
    ASSERT_EQ(postfx::dispatch(*single, own), postfx::Result::Ok);
    EXPECT_TRUE(identical(target(a), target(alone)));
  }
  glDeleteTextures(1, &water);
}

// The tile field is computed once per frame for six cube faces, each face's passes once: counted
// from the debug groups the plugin pushes around its passes.
std::vector<std::string>* debugGroups = nullptr;
void GLAPIENTRY recordGroup(GLenum source, GLenum type, GLuint, GLenum, GLsizei length,
                            const GLchar* message, const void*) {
  if (debugGroups && type == GL_DEBUG_TYPE_PUSH_GROUP && source == GL_DEBUG_SOURCE_APPLICATION)
    debugGroups->emplace_back(message, length >= 0 ? size_t(length) : std::strlen(message));
}

TEST_F(PostfxViewsTest, SharedPrePassRunsOncePerFrameForSixViews) {
  const glm::dvec3 faces[6] = {{1, -0.1, 0},  {-1, -0.1, 0}, {0.01, 1, 0},
                               {0.01, -1, 0}, {0, -0.1, 1},  {0, -0.1, -1}};
  std::vector<std::unique_ptr<Scene>> scenes;
  for (const glm::dvec3& look : faces) {
    SceneSpec s = seabedSpec({0.0, -2.0, 0.0}, look);
    s.width = s.height = 48;
    s.fovYDegrees = 90.0;
    scenes.push_back(std::make_unique<Scene>(s));
  }
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto fx = postfxtest::makeContext(kSeabed);
  std::vector<ViewPtr> views;
  std::vector<postfx::ViewDesc> descs;
  for (const auto& s : scenes) {
    views.push_back(makeView(*fx));
    descs.push_back(viewOf(views.back().get(), *s));
  }
  const postfx::FrameDesc shared =
      seabedFrame(*scenes[0], water, postfx::CausticsModel::TileIrradiance);

  std::vector<std::string> groups;
  debugGroups = &groups;
  glEnable(GL_DEBUG_OUTPUT);
  glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDebugMessageCallback(recordGroup, nullptr);
  glDebugMessageControl(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_PUSH_GROUP, GL_DONT_CARE, 0,
                        nullptr, GL_TRUE);
  const int frames = 3;
  for (int f = 0; f < frames; ++f)
    ASSERT_EQ(postfx::dispatch(*fx, shared, descs.data(), 6), postfx::Result::Ok)
        << postfx::lastError(fx.get());
  glDebugMessageCallback(nullptr, nullptr);
  glDisable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
  glDisable(GL_DEBUG_OUTPUT);
  debugGroups = nullptr;
  auto count = [&groups](const char* name) {
    int n = 0;
    for (const std::string& g : groups) n += g == name;
    return n;
  };
  ASSERT_GT(groups.size(), 0u) << "no debug groups recorded: debug output unsupported?";
  EXPECT_EQ(count("postfx"), frames);
  EXPECT_EQ(count("postfx.tile_irradiance"), frames) << "the shared pre-pass ran per view";
  // The camera is under water: every face's passes run, once per frame each.
  for (const auto& v : views) EXPECT_EQ(postfx::stats(*v).framesDispatched, std::uint64_t(frames));
  EXPECT_EQ(count("postfx.caustics"), 6 * frames);
  EXPECT_EQ(count("postfx.god_rays"), 6 * frames);
  // The timers: the shared pass once per frame in the context, each view's passes in the view.
  const postfx::FrameStats& shared0 = postfx::stats(*fx);
  EXPECT_EQ(shared0.framesDispatched, std::uint64_t(frames));
  EXPECT_TRUE(shared0.pass(postfx::Pass::TileIrradiance).present);
  EXPECT_FALSE(postfx::stats(*views[0]).pass(postfx::Pass::TileIrradiance).present);
  EXPECT_TRUE(postfx::stats(*views[0]).pass(postfx::Pass::Caustics).present);
  glDeleteTextures(1, &water);
}

// Every way a view list can be wrong is refused before anything is drawn into any view.
TEST_F(PostfxViewsTest, ARefusedViewLeavesEveryTargetUntouched) {
  Scene a(seabedSpec({0.0, -2.0, 0.0}, {0.0, -0.6, -1.0}));
  Scene b(seabedSpec({1.0, -2.0, 0.0}, {0.0, -0.6, -1.0}));
  Scene c(seabedSpec({2.0, -2.0, 0.0}, {0.0, -0.6, -1.0}));
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto fx = postfxtest::makeContext(kSeabed), other = postfxtest::makeContext(kSeabed);
  ViewPtr va = makeView(*fx), vb = makeView(*fx), vc = makeView(*fx), foreign = makeView(*other);
  postfx::View* destroyed = nullptr;
  ASSERT_EQ(postfx::createView(*fx, destroyed), postfx::Result::Ok);
  postfx::destroyView(*fx, destroyed);  // its address is kept only to be refused
  const postfx::FrameDesc shared = seabedFrame(a, water, postfx::CausticsModel::TileIrradiance);
  const glm::vec4 marker(0.25f, 0.5f, 0.75f, 1.0f);
  struct Case {
    const char* name;
    std::function<void(std::vector<postfx::ViewDesc>&)> spoil;
    const char* message;
  };
  const Case cases[] = {
      {"viewport outside the target",
       [](auto& v) {
         v[2].viewport = {50, 0, 50, 54};
       },
       "views[2]: viewport"},
      {"viewport of zero width",
       [](auto& v) {
         v[1].viewport = {0, 0, 0, 54};
       },
       "views[1]: viewport"},
      {"wrong normal format", [](auto& v) { v[2].normal.format = GL_RGBA32F; }, "views[2]: "},
      {"NaN camera", [](auto& v) { v[1].camera.position.x = std::nan(""); }, "views[1]: "},
      {"a view listed twice", [&](auto& v) { v[2].view = va.get(); }, "listed twice"},
      {"a null view", [](auto& v) { v[1].view = nullptr; }, "null"},
      {"another context's view", [&](auto& v) { v[0].view = foreign.get(); }, "this context"},
      {"a destroyed view", [&](auto& v) { v[1].view = destroyed; }, "not a live view"},
      {"overlapping viewports in one target",
       [&](auto& v) {
         v[1] = viewOf(vb.get(), a);
         v[0].viewport = {0, 0, 60, 54};
         v[1].viewport = {40, 0, 56, 54};
       },
       "overlap"},
  };
  for (const Case& k : cases) {
    SCOPED_TRACE(k.name);
    for (const Scene* s : {&a, &b, &c}) s->clearTarget(marker);
    std::vector<postfx::ViewDesc> views = {viewOf(va.get(), a), viewOf(vb.get(), b),
                                           viewOf(vc.get(), c)};
    k.spoil(views);
    EXPECT_NE(postfx::dispatch(*fx, shared, views.data(), 3), postfx::Result::Ok);
    EXPECT_NE(std::string(postfx::lastError(fx.get())).find(k.message), std::string::npos)
        << postfx::lastError(fx.get());
    for (const Scene* s : {&a, &b, &c})
      for (const glm::vec4& p : target(*s)) ASSERT_EQ(p, marker) << "a target was drawn into";
  }
  // A field every view shares is the frame's to fix: its refusal names no view.
  postfx::FrameDesc badTau = shared;
  badTau.caustics.tau = -1.0f;
  const std::vector<postfx::ViewDesc> all = {viewOf(va.get(), a), viewOf(vb.get(), b)};
  EXPECT_EQ(postfx::dispatch(*fx, badTau, all.data(), 2), postfx::Result::InvalidArgument);
  EXPECT_EQ(std::string(postfx::lastError(fx.get())).rfind("caustics.tau", 0), 0u)
      << postfx::lastError(fx.get());
  const postfx::ViewDesc one = viewOf(va.get(), a);
  EXPECT_EQ(postfx::dispatch(*fx, shared, &one, 0), postfx::Result::InvalidArgument);
  EXPECT_EQ(postfx::dispatch(*fx, shared, nullptr, 1), postfx::Result::InvalidArgument);
  EXPECT_EQ(postfx::dispatch(*fx, shared, &one, postfx::kMaxViews + 1),
            postfx::Result::InvalidArgument);
  // The same list, unspoilt, draws.
  const postfx::ViewDesc good[] = {viewOf(va.get(), a), viewOf(vb.get(), b), viewOf(vc.get(), c)};
  EXPECT_EQ(postfx::dispatch(*fx, shared, good, 3), postfx::Result::Ok)
      << postfx::lastError(fx.get());
  glDeleteTextures(1, &water);
}

// Split-screen: two cameras side by side in one target over one G-buffer; each half is exactly
// what a whole target of that size gets from a context of its own.
TEST_F(PostfxViewsTest, SplitScreenHalvesMatchWholeTargets) {
  SceneSpec left = seabedSpec({0.0, -2.0, 0.0}, {0.0, -0.6, -1.0});
  SceneSpec right = seabedSpec({2.0, -1.5, 1.0}, {0.5, -0.6, -0.8});
  left.width = right.width = 64;
  left.height = right.height = 72;
  Scene l(left), r(right);
  SceneSpec wide = left;
  wide.width = 128;
  Scene split(wide);  // its G-buffer: the left camera's scene in the left half, the right's
  for (auto [from, x] : {std::pair{&l, 0}, std::pair{&r, 64}}) {
    glCopyImageSubData(from->depth, GL_TEXTURE_2D, 0, 0, 0, 0, split.depth, GL_TEXTURE_2D, 0, x, 0,
                       0, 64, 72, 1);
    glCopyImageSubData(from->normal, GL_TEXTURE_2D, 0, 0, 0, 0, split.normal, GL_TEXTURE_2D, 0, x,
                       0, 0, 64, 72, 1);
    glCopyImageSubData(from->albedo, GL_TEXTURE_2D, 0, 0, 0, 0, split.albedo, GL_TEXTURE_2D, 0, x,
                       0, 0, 64, 72, 1);
  }
  split.clearTarget(glm::vec4(0.0f));
  l.clearTarget(glm::vec4(0.0f));
  r.clearTarget(glm::vec4(0.0f));
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto fx = postfxtest::makeContext(kSeabed), own = postfxtest::makeContext(kSeabed);
  ViewPtr vl = makeView(*fx), vr = makeView(*fx);
  const postfx::FrameDesc shared = seabedFrame(l, water, postfx::CausticsModel::TileIrradiance);
  postfx::ViewDesc views[] = {viewOf(vl.get(), split), viewOf(vr.get(), split)};
  views[0].camera = viewOf(nullptr, l).camera;
  views[1].camera = viewOf(nullptr, r).camera;
  views[0].viewport = {0, 0, 64, 72};
  views[1].viewport = {64, 0, 64, 72};
  ASSERT_EQ(postfx::dispatch(*fx, shared, views, 2), postfx::Result::Ok)
      << postfx::lastError(fx.get());
  ViewPtr ownL = makeView(*own), ownR = makeView(*own);
  for (auto [view, scene] : {std::pair{ownL.get(), &l}, std::pair{ownR.get(), &r}}) {
    const postfx::ViewDesc whole = viewOf(view, *scene);
    ASSERT_EQ(postfx::dispatch(*own, shared, &whole, 1), postfx::Result::Ok);
  }
  const std::vector<glm::vec4> image = target(split), imageL = target(l), imageR = target(r);
  int differing = 0;
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 64; ++x) {
      differing += image[size_t(y * 128 + x)] != imageL[size_t(y * 64 + x)];
      differing += image[size_t(y * 128 + 64 + x)] != imageR[size_t(y * 64 + x)];
    }
  EXPECT_GT(added(imageL), 1.0);
  EXPECT_GT(added(imageR), 1.0);
  EXPECT_EQ(differing, 0) << "pixels of the split target differ from the whole targets'";
  // Each view's raw output is written inside its viewport only.
  const std::vector<float> rawL =
      postfxtest::readRed(postfx::testing::rawCausticTexture(*vl), 128, 72);
  double outside = 0.0, inside = 0.0;
  for (int y = 0; y < 72; ++y)
    for (int x = 0; x < 128; ++x) (x < 64 ? inside : outside) += double(rawL[size_t(y * 128 + x)]);
  EXPECT_GT(inside, 1.0);
  EXPECT_EQ(outside, 0.0);
  glDeleteTextures(1, &water);
}

// Two eyes 6.4 cm apart: the caustic factor at a floor point seen by both is the same (the
// pattern lives in the world), and the god-ray planes lie in the same world positions.
TEST_F(PostfxViewsTest, StereoEyesSeeOneWorldPattern) {
  SceneSpec left = seabedSpec({0.0, -2.0, 0.0}, {0.0, -0.7, -1.0});
  left.width = 192;
  left.height = 108;
  left.sphere = false;
  SceneSpec right = left;
  right.camera.x += 0.064;
  Scene l(left), r(right);
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto fx = postfxtest::makeContext(kSeabed);
  ViewPtr vl = makeView(*fx), vr = makeView(*fx);
  auto correlation = [&](glm::dvec2 rightWaterShift) {
    postfx::FrameDesc shared = seabedFrame(l, water, postfx::CausticsModel::TileIrradiance);
    const postfx::ViewDesc views[] = {viewOf(vl.get(), l), viewOf(vr.get(), r)};
    EXPECT_EQ(postfx::dispatch(*fx, shared, views, 1), postfx::Result::Ok);
    shared.water.origin += rightWaterShift;
    EXPECT_EQ(postfx::dispatch(*fx, shared, views + 1, 1), postfx::Result::Ok);
    const int w = left.width, h = left.height;
    const auto rawL = postfxtest::readRed(postfx::testing::rawCausticTexture(*vl), w, h);
    const auto rawR = postfxtest::readRed(postfx::testing::rawCausticTexture(*vr), w, h);
    // Each right-eye floor pixel against the left eye's raw factor where the same world point
    // lies in the left image (bilinear).
    const glm::dmat4 leftClip = l.projection * glm::dmat4(l.view);
    double sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
    int n = 0;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const postfxtest::PixelTruth& t = r.truth(x, y);
        if (t.hit != postfxtest::Hit::Floor) continue;
        const glm::dvec3 world = right.camera + t.position;
        const glm::dvec4 c = leftClip * glm::dvec4(world - left.camera, 1.0);
        const glm::dvec2 p = (glm::dvec2(c) / c.w * 0.5 + 0.5) * glm::dvec2(w, h) - 0.5;
        const int x0 = int(std::floor(p.x)), y0 = int(std::floor(p.y));
        if (x0 < 1 || y0 < 1 || x0 >= w - 2 || y0 >= h - 2) continue;
        const double fx0 = p.x - x0, fy0 = p.y - y0;
        bool floorAll = true;
        for (int k = 0; k < 4; ++k)
          floorAll = floorAll && l.truth(x0 + (k & 1), y0 + (k >> 1)).hit == postfxtest::Hit::Floor;
        if (!floorAll) continue;
        auto at = [&](int i, int j) { return double(rawL[size_t(j * w + i)]); };
        const double lv = (1 - fy0) * ((1 - fx0) * at(x0, y0) + fx0 * at(x0 + 1, y0)) +
                          fy0 * ((1 - fx0) * at(x0, y0 + 1) + fx0 * at(x0 + 1, y0 + 1));
        const double rv = rawR[size_t(y * w + x)];
        sx += lv;
        sy += rv;
        sxx += lv * lv;
        syy += rv * rv;
        sxy += lv * rv;
        ++n;
      }
    EXPECT_GT(n, w * h / 4);
    const double cov = sxy / n - sx / n * sy / n;
    return cov / std::sqrt((sxx / n - sx / n * sx / n) * (syy / n - sy / n * sy / n));
  };
  const double same = correlation({0.0, 0.0});
  // The metric sees a different pattern: the right eye's water moved by a third of a tile.
  const double shifted = correlation({3.3, 1.7});
  EXPECT_GT(same, 0.97) << "the eyes disagree about the caustics at one world point";
  EXPECT_LT(shifted, same - 0.3) << "the metric does not tell patterns apart";
  RecordProperty("stereo_raw_correlation", std::to_string(same));
  std::printf("stereo: raw factor correlation at shared world points %.4f (water moved: %.4f)\n",
              same, shifted);

  // God rays: both eyes' grids pass through the same world planes (no per-eye phase).
  postfx::FrameDesc frame = seabedFrame(l, water, postfx::CausticsModel::TileIrradiance);
  postfx::detail::GodRayGridPivot pl, pr;
  frame.camera.position = left.camera;
  const auto bl = postfx::detail::buildGodRaysBlock(frame, 192, 108, pl);
  frame.camera.position = right.camera;
  const auto br = postfx::detail::buildGodRaysBlock(frame, 192, 108, pr);
  const double spacing = bl.gridX.w;
  for (int axis = 0; axis < 2; ++axis) {
    const glm::dvec3 dir =
        axis == 0 ? glm::dvec3(glm::vec3(bl.gridX)) : glm::dvec3(glm::vec3(bl.gridZ));
    // A plane lies at (camera . axis) - phase + k * spacing.
    const double planeL =
        glm::dot(left.camera, dir) - double(axis == 0 ? bl.gridOffset.x : bl.gridOffset.y);
    const double planeR =
        glm::dot(right.camera, dir) - double(axis == 0 ? br.gridOffset.x : br.gridOffset.y);
    const double apart = std::remainder(planeL - planeR, spacing);
    EXPECT_LT(std::abs(apart), 1e-5) << "axis " << axis;
  }
  glDeleteTextures(1, &water);
}

// Ending a view frees what it held: its raw output and reduced-resolution textures are deleted.
TEST_F(PostfxViewsTest, EndingAViewFreesItsMemory) {
  Scene a(seabedSpec({0.0, -2.0, 0.0}, {0.0, -0.6, -1.0}));
  const GLuint water = postfxtest::makeWaterTexture(64, 3, 0.05);
  auto fx = postfxtest::makeContext(kSeabed);
  postfx::View* view = nullptr;
  ASSERT_EQ(postfx::createView(*fx, view), postfx::Result::Ok);
  postfx::FrameDesc shared = seabedFrame(a, water, postfx::CausticsModel::TileIrradiance);
  shared.caustics.tileLookupResolution = postfx::CausticsLookupResolution::Half;
  const postfx::ViewDesc desc = viewOf(view, a);
  ASSERT_EQ(postfx::dispatch(*fx, shared, &desc, 1), postfx::Result::Ok)
      << postfx::lastError(fx.get());
  const std::uint64_t bytes = postfx::testing::viewAllocatedBytes(*view);
  // Raw R16F (96 x 54), lookups R32UI (48 x 27), god rays RG32UI (48 x 27).
  EXPECT_EQ(bytes, 96u * 54u * 2u + 48u * 27u * 4u + 48u * 27u * 8u);
  const GLuint raw = postfx::testing::rawCausticTexture(*view);
  ASSERT_TRUE(glIsTexture(raw));
  postfx::destroyView(*fx, view);
  EXPECT_FALSE(glIsTexture(raw)) << "the view's raw output outlived it";
  // The context goes on without it; a null view is ignored.
  postfx::destroyView(*fx, nullptr);
  ASSERT_EQ(postfx::dispatch(*fx, shared), postfx::Result::Ok);
  glDeleteTextures(1, &water);
}

}  // namespace
