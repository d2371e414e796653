// View-list fuzz (postfx/views.h): a deterministic seed drives a few hundred multi-view
// dispatches, each a valid list of up to four views (two of them sharing one target side by
// side) with one thing spoiled: the count, a view handle (null, repeated, another context's), a
// viewport (IEEE-free but wild integers: negative, zero, past the target, INT_MAX), a camera, a
// view's own shadow map, or a view's texture. Every case must end one of two ways:
//   * a non-Ok Result whose message names the view or the list, every target bit-identical and
//     GL state as the host left it;
//   * Ok with every value of every target finite and no GL error;
// and the next ordinary list must draw what a fresh context draws.
#include <gtest/gtest.h>
#include <postfx/testing.h>
#include <postfx/views.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "fuzz_values.h"
#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "postfx_views_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;
using postfxfuzz::Rng;
using postfxfuzz::wild;
using postfxfuzz::wildInt;

constexpr std::uint64_t kSeed = 0x3057;
constexpr int kCases = 240;
const glm::vec4 kMarker(0.125f, 0.25f, 0.5f, 1.0f);

class PostfxViewsFuzzTest : public testsupport::GlTest {};

bool allFinite(const std::vector<glm::vec4>& image) {
  for (const glm::vec4& p : image)
    if (!std::isfinite(p.r) || !std::isfinite(p.g) || !std::isfinite(p.b) || !std::isfinite(p.a))
      return false;
  return true;
}

TEST_F(PostfxViewsFuzzTest, EveryListIsRefusedCleanlyOrDrawnFinite) {
  const postfx::Feature features = postfx::Feature::Caustics | postfx::Feature::GodRays |
                                   postfx::Feature::ShadowMask | postfx::testing::RawCausticOutput;
  // Two scenes of their own, and a wide one whose target two views share side by side.
  SceneSpec small;
  small.width = 32;
  small.height = 18;
  Scene a(small), b(small);
  SceneSpec wideSpec = small;
  wideSpec.width = 64;
  Scene wide(wideSpec);
  const GLuint water = makeWaterTexture(32, 3, 0.02);
  GLuint shadow = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &shadow);
  glTextureStorage2D(shadow, 1, GL_DEPTH_COMPONENT32F, 16, 16);
  const float one = 1.0f;
  glClearTexImage(shadow, 0, GL_DEPTH_COMPONENT, GL_FLOAT, &one);

  auto fx = makeContext(features), fresh = makeContext(features), other = makeContext(features);
  std::vector<ViewPtr> views, freshViews;
  for (int i = 0; i < 4; ++i) {
    views.push_back(makeView(*fx));
    freshViews.push_back(makeView(*fresh));
  }
  const ViewPtr foreign = makeView(*other);

  postfx::FrameDesc frame = makeFrame(a, water, 3);
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  frame.godRays.sampleCount = 8;
  frame.shadow.depth = {shadow, GL_DEPTH_COMPONENT32F};
  frame.shadow.worldToLightClip = glm::dmat4(0.05);
  frame.shadow.worldToLightClip[3][3] = 1.0;
  auto ordinaryList = [&](std::vector<ViewPtr>& handles) {
    std::vector<postfx::ViewDesc> list = {viewOf(handles[0].get(), a), viewOf(handles[1].get(), b),
                                          viewOf(handles[2].get(), wide),
                                          viewOf(handles[3].get(), wide)};
    list[2].viewport = {0, 0, 32, 18};
    list[3].viewport = {32, 0, 32, 18};
    return list;
  };
  const Scene* scenes[] = {&a, &b, &wide};
  auto clearAll = [&] {
    for (const Scene* s : scenes) s->clearTarget(kMarker);
  };
  auto readAll = [&] {
    std::vector<std::vector<glm::vec4>> images;
    for (const Scene* s : scenes)
      images.push_back(readRgba(s->target, s->spec().width, s->spec().height));
    return images;
  };

  Rng rng(kSeed);
  int refused = 0, drawn = 0, failures = 0;
  for (int c = 0; c < kCases; ++c) {
    std::vector<postfx::ViewDesc> list = ordinaryList(views);
    // Entries past the four a list fills read as a default ViewDesc (no view): a count up to
    // kMaxViews reads only what the host holds.
    list.resize(postfx::kMaxViews + 1);
    int count = 4;
    postfx::SunShadowMap ownShadow = frame.shadow;
    std::string what;
    const int victim = rng.below(4);
    switch (rng.below(7)) {
      case 0:
        count = wildInt(rng, 4);
        what = "count " + std::to_string(count);
        break;
      case 1: {
        const int kind = rng.below(3);
        list[size_t(victim)].view = kind == 0   ? nullptr
                                    : kind == 1 ? list[size_t((victim + 1) % 4)].view
                                                : foreign.get();
        what = "handle kind " + std::to_string(kind);
        break;
      }
      case 2: {
        postfx::Viewport& v = list[size_t(victim)].viewport;
        v = {wildInt(rng, 8), wildInt(rng, 4), wildInt(rng, 32), wildInt(rng, 18)};
        what = "viewport " + std::to_string(v.x) + "," + std::to_string(v.y) + " " +
               std::to_string(v.width) + "x" + std::to_string(v.height);
        break;
      }
      case 3: {
        glm::dvec3& p = list[size_t(victim)].camera.position;
        p[rng.below(3)] = wild(rng, 1.0);
        what = "camera";
        break;
      }
      case 4:
        ownShadow.bias = static_cast<float>(wild(rng, 0.02));
        ownShadow.worldToLightClip[rng.below(4)][rng.below(4)] = wild(rng, 0.05);
        list[size_t(victim)].shadow = &ownShadow;
        what = "own shadow";
        break;
      case 5:
        list[size_t(victim)].normal.format = GL_RGBA8;
        what = "normal format";
        break;
      default:
        list[size_t(victim)].target = {a.target, a.targetFormat};  // may overlap view 0
        what = "target";
        break;
    }
    SCOPED_TRACE("case " + std::to_string(c) + ": " + what);
    clearAll();
    const GlSnapshot before = snapshotGlState();
    const Result r = postfx::dispatch(*fx, frame, list.data(), count);
    const GlSnapshot after = snapshotGlState();
    const auto images = readAll();
    if (r != Result::Ok) {
      ++refused;
      // A list's message names the list or the view (views[i]: ...), a frame's the frame.
      const std::string message = postfx::lastError(fx.get());
      if (message.find("view") == std::string::npos && message.find("frame") == std::string::npos)
        ++failures, ADD_FAILURE() << "a message that names neither view nor frame: " << message;
      bool untouched = true;
      for (const auto& image : images)
        for (const glm::vec4& p : image) untouched = untouched && p == kMarker;
      if (!untouched)
        ++failures, ADD_FAILURE() << "refused, but a target was drawn into: " << message;
      if (before != after) ++failures, ADD_FAILURE() << "refused, but GL state changed";
    } else {
      ++drawn;
      for (const auto& image : images)
        if (!allFinite(image)) ++failures, ADD_FAILURE() << "drawn, not finite";
      if (before != after) ++failures, ADD_FAILURE() << "drawn, but GL state not restored";
    }
    if (glGetError() != GL_NO_ERROR) ++failures, ADD_FAILURE() << "GL error";
    if (failures > 25) break;
  }
  std::printf("views fuzz: %d lists, %d refused, %d drawn\n", kCases, refused, drawn);
  EXPECT_GT(refused, kCases / 4);
  EXPECT_GT(drawn, kCases / 20);

  // The next ordinary list draws what a fresh context draws (each has run as many frames since
  // the ring filled, so their state is the same: a pivot at the origin and no other history).
  clearAll();
  std::vector<postfx::ViewDesc> list = ordinaryList(views);
  ASSERT_EQ(postfx::dispatch(*fx, frame, list.data(), 4), Result::Ok)
      << postfx::lastError(fx.get());
  const auto afterFuzz = readAll();
  clearAll();
  list = ordinaryList(freshViews);
  ASSERT_EQ(postfx::dispatch(*fresh, frame, list.data(), 4), Result::Ok);
  const auto freshImages = readAll();
  for (size_t i = 0; i < afterFuzz.size(); ++i)
    EXPECT_EQ(std::memcmp(afterFuzz[i].data(), freshImages[i].data(),
                          afterFuzz[i].size() * sizeof(glm::vec4)),
              0)
        << "scene " << i << " differs from a fresh context's after the fuzz";
  glDeleteTextures(1, &water);
  glDeleteTextures(1, &shadow);
}

}  // namespace
