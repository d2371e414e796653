// Local water regions (postfx/local_water.h): physics and contracts. A flat region gives flat
// water's light whatever the sea around it does; an Add region of zero height and everything
// outside a region change nothing, bit for bit; a circular ripple focuses a ring at its paraxial
// depth; the flux over a rippled region is conserved; a region 1e6 m from the origin draws what
// one at the origin does; bad regions are refused with nothing drawn; god rays read the regions'
// light; the memory estimate is what GL holds.
#include <gtest/gtest.h>
#include <postfx/testing.h>
#include <postfx/views.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/context.h"
#include "core/frame_geometry.h"
#include "core/frame_plan.h"
#include "core/gl_sizes.h"
#include "core/memory_estimate.h"
#include "gl_fixture.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"
#include "postfx_views_util.h"
#include "seabed_caustics/local_water_layout.h"

namespace {

using postfxtest::Hit;
using postfxtest::Scene;
using postfxtest::SceneSpec;

class PostfxLocalWaterTest : public testsupport::GlTest {};

constexpr postfx::Feature kLocal = postfxtest::kRaw | postfx::Feature::LocalWater;
constexpr double kIor = 1.333;

// A test's own GL texture, deleted with it.
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

// (dh/du, dh/dv, h) of a region's surface at local (u, v), metres.
using Surface = std::function<glm::dvec3(glm::dvec2)>;

// A host region texture: GL_TEXTURE_2D RGBA32F, `size` texels a side over `extent` metres.
GLuint makeRegionTexture(int size, glm::dvec2 extent, const Surface& surface,
                         GLenum format = GL_RGBA32F) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, format, size, size);
  std::vector<glm::vec4> texels(static_cast<std::size_t>(size) * size);
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const glm::dvec2 local = (glm::dvec2(i + 0.5, j + 0.5) / double(size) - 0.5) * extent;
      const glm::dvec3 s = surface(local);
      texels[static_cast<std::size_t>(j) * size + i] = glm::vec4(glm::vec3(s), 0.0f);
    }
  glTextureSubImage2D(t, 0, 0, 0, size, size, GL_RGBA, GL_FLOAT, texels.data());
  return t;
}

glm::dvec3 flatSurface(glm::dvec2) {
  return glm::dvec3(0.0);
}

// Ripples of a few directions and wavelengths (slopes up to ~0.15).
glm::dvec3 rippledSurface(glm::dvec2 p) {
  glm::dvec3 s(0.0);
  const double waves[][4] = {
      {0.9, 0.3, 0.012, 0.0}, {-0.4, 1.1, 0.008, 1.0}, {1.7, -0.8, 0.004, 2.0}};
  for (const auto& w : waves) {
    const glm::dvec2 k = 2.0 * 3.141592653589793 * glm::dvec2(w[0], w[1]);
    const double phase = glm::dot(k, p) + w[3];
    s += glm::dvec3(w[2] * k.x * std::cos(phase), w[2] * k.y * std::cos(phase),
                    w[2] * std::sin(phase));
  }
  return s;
}

// A camera `height` above the water looking straight down (almost: lookAt needs a horizon) at a
// floor `depth` below it, no sphere.
SceneSpec downSpec(double depth, int size = 96, double height = 1.0) {
  SceneSpec s;
  s.width = size;
  s.height = size;
  s.camera = glm::dvec3(0.0, height, 0.0);
  s.lookDirection = glm::dvec3(0.0, -1.0, -1e-3);
  s.floorY = -depth;
  s.sphere = false;
  return s;
}

postfx::LocalWater region(GLuint texture, glm::dvec2 centre, glm::dvec2 size,
                          postfx::LocalWaterMode mode, float maxDepth) {
  postfx::LocalWater r;
  r.centre = centre;
  r.size = size;
  r.texture = {texture, GL_RGBA32F};
  r.mode = mode;
  r.edgeBlend = 0.5f;
  r.gridResolution = 128;
  r.depthLayers = 4;
  r.maxDepth = maxDepth;
  return r;
}

std::vector<float> raw(const postfx::Context& fx, const Scene& s) {
  return postfxtest::readRed(postfx::testing::rawCausticTexture(fx), s.spec().width,
                             s.spec().height);
}

std::vector<glm::vec4> target(const Scene& s) {
  return postfxtest::readRgba(s.target, s.spec().width, s.spec().height);
}

bool identical(const std::vector<glm::vec4>& a, const std::vector<glm::vec4>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0;
}

// Draws `frame` into a cleared target; the raw output and the target after it.
struct Drawn {
  std::vector<float> raw;
  std::vector<glm::vec4> target;
};
Drawn draw(postfx::Context& fx, const Scene& scene, const postfx::FrameDesc& frame) {
  scene.clearTarget(glm::vec4(0.0f));
  EXPECT_EQ(postfx::dispatch(fx, frame), postfx::Result::Ok) << postfx::lastError(&fx);
  return {raw(fx, scene), target(scene)};
}

// A flat region over a stormy sea (Replace) gives exactly the light of flat water: the region's
// grid refracts straight down with a transmittance ratio of 1 and its triangles keep their area.
TEST_F(PostfxLocalWaterTest, FlatReplaceRegionGivesFlatWatersLight) {
  Scene scene(downSpec(4.0));
  const OwnedTexture calm(postfxtest::makeWaterTexture(32, 3, 0.0));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.05));
  const OwnedTexture flat(makeRegionTexture(32, {20.0, 20.0}, flatSurface));
  auto fx = postfxtest::makeContext(kLocal);
  const Drawn reference = draw(*fx, scene, postfxtest::makeFrame(scene, calm, 3));

  postfx::FrameDesc frame = postfxtest::makeFrame(scene, stormy, 3);
  const Drawn sea = draw(*fx, scene, frame);
  const postfx::LocalWater pool =
      region(flat, {0.0, 0.0}, {20.0, 20.0}, postfx::LocalWaterMode::Replace, 4.0f);
  frame.water.localWater = &pool;
  frame.water.localWaterCount = 1;
  const Drawn pooled = draw(*fx, scene, frame);

  double worst = 0.0, seaDeparture = 0.0;
  int floor = 0;
  for (int y = 0; y < scene.spec().height; ++y)
    for (int x = 0; x < scene.spec().width; ++x) {
      if (scene.truth(x, y).hit != Hit::Floor) continue;
      const std::size_t i = std::size_t(y) * scene.spec().width + x;
      ++floor;
      worst = std::max(worst, double(std::abs(pooled.raw[i] - reference.raw[i])));
      seaDeparture = std::max(seaDeparture, double(std::abs(sea.raw[i] - reference.raw[i])));
    }
  std::printf("%d floor pixels: flat region vs flat water %.2e (the stormy sea departs %.3f)\n",
              floor, worst, seaDeparture);
  ASSERT_GT(floor, 1000);
  EXPECT_GT(seaDeparture, 0.2) << "the sea beneath must be far from flat for this to mean much";
  EXPECT_LT(worst, 2e-3);  // R16F's rounding of values ~1
}

// An Add region of zero height changes nothing, bit for bit: its two fields come from the same
// grid and cancel exactly. The same frame in a context without the feature draws the same too.
TEST_F(PostfxLocalWaterTest, ZeroHeightAddRegionChangesNothing) {
  Scene scene(downSpec(3.0));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.02));
  const OwnedTexture zero(makeRegionTexture(16, {6.0, 6.0}, flatSurface));
  for (const postfx::CausticsModel model :
       {postfx::CausticsModel::TileIrradiance, postfx::CausticsModel::RayDeviation}) {
    SCOPED_TRACE(int(model));
    auto fx = postfxtest::makeContext(kLocal | postfx::Feature::GodRays);
    auto without = postfxtest::makeContext(postfxtest::kRaw | postfx::Feature::GodRays);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, stormy, 3);
    frame.caustics.model = model;
    const Drawn before = draw(*fx, scene, frame);
    const Drawn plain = draw(*without, scene, frame);
    const postfx::LocalWater wake =
        region(zero, {0.5, -0.5}, {6.0, 6.0}, postfx::LocalWaterMode::Add, 3.0f);
    frame.water.localWater = &wake;
    frame.water.localWaterCount = 1;
    const Drawn after = draw(*fx, scene, frame);
    EXPECT_TRUE(identical(before.target, after.target));
    EXPECT_EQ(std::memcmp(before.raw.data(), after.raw.data(), before.raw.size() * 4), 0);
    EXPECT_TRUE(identical(before.target, plain.target)) << "the feature alone changes nothing";
    EXPECT_TRUE(postfx::stats(*fx).pass(postfx::Pass::LocalWater).present);
  }
}

// Where a pixel's light entered the water outside every region, its light is bit-identical to a
// frame without them; inside, the region's ripples show.
TEST_F(PostfxLocalWaterTest, OutsideTheRegionNothingChanges) {
  Scene scene(downSpec(3.0, 128));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.02));
  const OwnedTexture ripples(makeRegionTexture(128, {4.0, 6.0}, rippledSurface));
  auto fx = postfxtest::makeContext(kLocal);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, stormy, 3);
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  const Drawn before = draw(*fx, scene, frame);
  // Turned 0.4 rad; its centre left of the camera, so the view holds both sides of its edge.
  postfx::LocalWater pool =
      region(ripples, {-1.5, 0.3}, {4.0, 6.0}, postfx::LocalWaterMode::Replace, 3.0f);
  pool.rotation = 0.4;
  frame.water.localWater = &pool;
  frame.water.localWaterCount = 1;
  const Drawn after = draw(*fx, scene, frame);

  const glm::dvec3 down =
      postfx::detail::refractedSunDown(glm::normalize(frame.sun.direction), kIor);
  const glm::dvec2 drift = glm::dvec2(down.x, down.z) / -down.y;
  const glm::dvec2 u(std::cos(pool.rotation), -std::sin(pool.rotation)), v(-u.y, u.x);
  int outside = 0, inside = 0, insideChanged = 0, outsideChanged = 0;
  for (int y = 0; y < scene.spec().height; ++y)
    for (int x = 0; x < scene.spec().width; ++x) {
      const postfxtest::PixelTruth& t = scene.truth(x, y);
      if (t.hit != Hit::Floor) continue;
      const glm::dvec3 world = t.position + scene.spec().camera;
      const double depth = -world.y;
      const glm::dvec2 entry = glm::dvec2(world.x, world.z) - drift * depth - pool.centre;
      const glm::dvec2 local(glm::dot(entry, u), glm::dot(entry, v));
      const glm::dvec2 margin = 0.5 * pool.size - glm::abs(local);
      const double distance = std::min(margin.x, margin.y);
      const std::size_t i = std::size_t(y) * scene.spec().width + x;
      const bool same = std::memcmp(&before.target[i], &after.target[i], sizeof(glm::vec4)) == 0;
      if (distance < -0.02) {
        ++outside;
        outsideChanged += same ? 0 : 1;
      } else if (distance > double(pool.edgeBlend)) {
        ++inside;
        insideChanged += std::abs(after.raw[i] - before.raw[i]) > 0.02f ? 1 : 0;
      }
    }
  std::printf("outside %d pixels (%d changed), inside %d (%d changed by > 0.02)\n", outside,
              outsideChanged, inside, insideChanged);
  ASSERT_GT(outside, 1000);
  ASSERT_GT(inside, 1000);
  EXPECT_EQ(outsideChanged, 0);
  EXPECT_GT(insideChanged, inside / 2);
}

// A circular ripple's crest is a ring-shaped cylindrical lens of curvature A / sigma^2 across it:
// under a sun at the zenith its light focuses into a ring of its radius at the paraxial depth
// 1 / ((1 - 1/n) * curvature): the ring's excess light is narrowest there (before it, the band
// is still converging; past it, two folds part).
TEST_F(PostfxLocalWaterTest, CircularRippleFocusesARingAtItsParaxialDepth) {
  const double ringRadius = 1.2, sigma = 0.12, focus = 2.0;
  const double amplitude = sigma * sigma / ((1.0 - 1.0 / kIor) * focus);
  const Surface ring = [&](glm::dvec2 p) {
    const double r = std::max(glm::length(p), 1e-9);
    const double g =
        amplitude * std::exp(-0.5 * (r - ringRadius) * (r - ringRadius) / (sigma * sigma));
    const double dhdr = -g * (r - ringRadius) / (sigma * sigma);
    return glm::dvec3(dhdr * p.x / r, dhdr * p.y / r, g);
  };
  const OwnedTexture surface(makeRegionTexture(256, {4.0, 4.0}, ring));
  const OwnedTexture calm(postfxtest::makeWaterTexture(32, 3, 0.0));
  auto fx = postfxtest::makeContext(kLocal);
  const double depths[] = {0.5 * focus, 0.75 * focus, focus, 1.5 * focus, 2.0 * focus};
  constexpr int kDepths = 5;
  double width[kDepths] = {}, centre[kDepths] = {};
  for (int d = 0; d < kDepths; ++d) {
    // The camera 2.5 m above the floor: the same pixel footprint at every depth.
    Scene scene(downSpec(depths[d], 192, 2.5 - depths[d]));
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, calm, 3);
    frame.sun.direction = glm::dvec3(0.0, 1.0, 0.0);
    frame.caustics.surfaceFadeDepth = 0.0f;
    postfx::LocalWater pool =
        region(surface, {0.0, 0.0}, {4.0, 4.0}, postfx::LocalWaterMode::Replace, float(depths[d]));
    pool.gridResolution = 512;
    pool.edgeBlend = 0.0f;
    frame.water.localWater = &pool;
    frame.water.localWaterCount = 1;
    const Drawn drawn = draw(*fx, scene, frame);
    // The ring's excess light over flat water's, by radius: its centroid and RMS width.
    double sum = 0.0, first = 0.0, second = 0.0;
    for (int y = 0; y < scene.spec().height; ++y)
      for (int x = 0; x < scene.spec().width; ++x) {
        const postfxtest::PixelTruth& t = scene.truth(x, y);
        if (t.hit != Hit::Floor) continue;
        const glm::dvec3 world = t.position + scene.spec().camera;
        const double r = glm::length(glm::dvec2(world.x, world.z));
        if (std::abs(r - ringRadius) > 0.4) continue;
        // Per unit floor area: pixels on a ring of radius r are r times as many.
        const double excess =
            std::max(double(drawn.raw[std::size_t(y) * scene.spec().width + x]) - 1.0, 0.0);
        sum += excess;
        first += excess * r;
        second += excess * r * r;
      }
    centre[d] = first / sum;
    width[d] = std::sqrt(std::max(second / sum - centre[d] * centre[d], 0.0));
    std::printf("depth %.2f m: ring of excess light at %.3f m, rms width %.1f mm\n", depths[d],
                centre[d], 1e3 * width[d]);
  }
  EXPECT_NEAR(centre[2], ringRadius, 0.02) << "the ring lands under its crest";
  for (int d : {0, 1, 3, 4}) EXPECT_LT(width[2], width[d]) << "narrowest at the paraxial depth";
}

// Two regions of different grids and modes share one frame's texture: each one's light is what
// it is alone (to float rounding of the lookups' coordinates), and they do not see each other.
TEST_F(PostfxLocalWaterTest, RegionsDoNotDisturbEachOther) {
  Scene scene(downSpec(3.0, 128));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.02));
  const OwnedTexture ripples(makeRegionTexture(128, {3.0, 3.0}, rippledSurface));
  auto fx = postfxtest::makeContext(kLocal);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, stormy, 3);
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  postfx::LocalWater regions[2] = {
      region(ripples, {-1.6, 0.0}, {3.0, 3.0}, postfx::LocalWaterMode::Replace, 3.0f),
      region(ripples, {1.6, 0.2}, {3.0, 3.0}, postfx::LocalWaterMode::Add, 3.0f)};
  regions[0].gridResolution = 96;
  regions[1].gridResolution = 160;
  regions[1].rotation = -0.3;
  frame.water.localWater = regions;
  frame.water.localWaterCount = 2;
  const Drawn both = draw(*fx, scene, frame);
  std::vector<float> alone[2];
  for (int r = 0; r < 2; ++r) {
    frame.water.localWater = &regions[r];
    frame.water.localWaterCount = 1;
    alone[r] = draw(*fx, scene, frame).raw;
  }
  frame.water.localWaterCount = 0;
  const std::vector<float> none = draw(*fx, scene, frame).raw;
  double worst = 0.0, largest = 0.0;
  int touched[2] = {0, 0}, overlap = 0;
  for (std::size_t i = 0; i < both.raw.size(); ++i) {
    // A region alone leaves a pixel it does not reach exactly as without regions (tested
    // above); where region 0 did not reach, the pair must draw region 1's light, and so on.
    const bool by0 = alone[0][i] != none[i], by1 = alone[1][i] != none[i];
    touched[0] += by0;
    touched[1] += by1;
    overlap += by0 && by1;
    const float expected = by0 ? alone[0][i] : alone[1][i];
    worst = std::max(worst, double(std::abs(both.raw[i] - expected)));
    largest = std::max(largest, double(both.raw[i]));
  }
  std::printf("regions reach %d and %d pixels (%d both)\n", touched[0], touched[1], overlap);
  ASSERT_GT(touched[0], 1000);
  ASSERT_GT(touched[1], 1000);
  EXPECT_EQ(overlap, 0);
  std::printf("two regions: largest difference from each alone %.2e of light up to %.2f\n", worst,
              largest);
  EXPECT_LT(worst, 2e-3 * largest);
}

// Several views of one frame (postfx/views.h) share the regions' light, computed once: each
// view's image is bit-identical to a context of its own drawing that camera alone.
TEST_F(PostfxLocalWaterTest, ViewsShareTheRegionsLight) {
  SceneSpec tilted = downSpec(3.0, 96);
  tilted.camera = glm::dvec3(1.0, 0.5, 0.5);
  tilted.lookDirection = glm::dvec3(-0.4, -1.0, -0.3);
  Scene a(downSpec(3.0, 96)), b(tilted), ownA(a.spec()), ownB(b.spec());
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.02));
  const OwnedTexture ripples(makeRegionTexture(128, {5.0, 5.0}, rippledSurface));
  postfx::LocalWater regions[2] = {
      region(ripples, {-0.5, 0.3}, {5.0, 5.0}, postfx::LocalWaterMode::Replace, 3.0f),
      region(ripples, {2.5, -1.0}, {5.0, 5.0}, postfx::LocalWaterMode::Add, 3.0f)};
  regions[1].rotation = 0.7;
  auto shared = postfxtest::makeContext(kLocal | postfx::Feature::GodRays);
  auto contextA = postfxtest::makeContext(kLocal | postfx::Feature::GodRays);
  auto contextB = postfxtest::makeContext(kLocal | postfx::Feature::GodRays);
  const postfxtest::ViewPtr viewA = postfxtest::makeView(*shared),
                            viewB = postfxtest::makeView(*shared);
  auto frameOf = [&](const Scene& scene) {
    postfx::FrameDesc f = postfxtest::makeFrame(scene, stormy, 3);
    f.caustics.model = postfx::CausticsModel::TileIrradiance;
    f.water.localWater = regions;
    f.water.localWaterCount = 2;
    return f;
  };
  for (const Scene* s : {&a, &b, &ownA, &ownB}) s->clearTarget(glm::vec4(0.0f));
  const postfx::ViewDesc list[2] = {postfxtest::viewOf(viewA.get(), a),
                                    postfxtest::viewOf(viewB.get(), b)};
  ASSERT_EQ(postfx::dispatch(*shared, frameOf(a), list, 2), postfx::Result::Ok)
      << postfx::lastError(shared.get());
  ASSERT_EQ(postfx::dispatch(*contextA, frameOf(ownA)), postfx::Result::Ok);
  ASSERT_EQ(postfx::dispatch(*contextB, frameOf(ownB)), postfx::Result::Ok);
  EXPECT_TRUE(identical(target(a), target(ownA)));
  EXPECT_TRUE(identical(target(b), target(ownB)));
  EXPECT_FALSE(identical(target(a), target(b)));
}

// The light a rippled region lets through is conserved: over its interior the floor's mean equals
// flat water's (Fresnel's few tenths of a percent aside), however the ripples focus it.
TEST_F(PostfxLocalWaterTest, RippledRegionConservesFlux) {
  Scene scene(downSpec(2.5, 128, 1.5));
  const OwnedTexture calm(postfxtest::makeWaterTexture(32, 3, 0.0));
  const OwnedTexture ripples(makeRegionTexture(256, {12.0, 12.0}, rippledSurface));
  auto fx = postfxtest::makeContext(kLocal);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, calm, 3);
  frame.caustics.surfaceFadeDepth = 0.0f;
  const Drawn flat = draw(*fx, scene, frame);
  postfx::LocalWater pool =
      region(ripples, {0.0, 0.0}, {12.0, 12.0}, postfx::LocalWaterMode::Replace, 2.5f);
  pool.gridResolution = 256;
  frame.water.localWater = &pool;
  frame.water.localWaterCount = 1;
  const Drawn rippled = draw(*fx, scene, frame);
  double flatSum = 0.0, rippledSum = 0.0, contrast = 0.0;
  int n = 0;
  for (std::size_t i = 0; i < flat.raw.size(); ++i) {
    if (!(flat.raw[i] > 0.0f)) continue;
    const double f = flat.raw[i], r = rippled.raw[i];
    flatSum += f;
    rippledSum += r;
    contrast += (r - f) * (r - f);
    ++n;
  }
  const double ratio = rippledSum / flatSum;
  std::printf("%d pixels: rippled / flat light %.4f, rms departure %.3f\n", n, ratio,
              std::sqrt(contrast / n));
  ASSERT_GT(n, 5000);
  EXPECT_GT(std::sqrt(contrast / n), 0.1) << "the ripples must make caustics";
  EXPECT_NEAR(ratio, 1.0, 0.02);
}

// Everything 1e6 m from the origin (camera, water origin, region): the light is what it is at
// the origin to float noise, as the region's frame is taken relative to the camera in double.
TEST_F(PostfxLocalWaterTest, FarFromTheOriginDrawsTheSame) {
  Scene scene(downSpec(3.0));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.02));
  const OwnedTexture ripples(makeRegionTexture(128, {8.0, 8.0}, rippledSurface));
  auto fx = postfxtest::makeContext(kLocal);
  std::vector<float> near, far;
  for (const glm::dvec3 offset : {glm::dvec3(0.0), glm::dvec3(1e6, 0.0, -1e6)}) {
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, stormy, 3, offset);
    frame.water.origin = glm::dvec2(offset.x, offset.z);
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    postfx::LocalWater wake = region(ripples, glm::dvec2(offset.x + 0.3, offset.z - 0.2),
                                     {8.0, 8.0}, postfx::LocalWaterMode::Add, 3.0f);
    frame.water.localWater = &wake;
    frame.water.localWaterCount = 1;
    (offset.x == 0.0 ? near : far) = draw(*fx, scene, frame).raw;
  }
  double worst = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < near.size(); ++i) {
    worst = std::max(worst, double(std::abs(near[i] - far[i])));
    largest = std::max(largest, double(near[i]));
  }
  std::printf("1e6 m away: largest difference %.2e of light up to %.2f\n", worst, largest);
  EXPECT_LT(worst, 0.01 * largest);
}

// Bad regions are refused with a message naming the field, and the target is left as it was.
TEST_F(PostfxLocalWaterTest, BadRegionsAreRefusedAndDrawNothing) {
  Scene scene(downSpec(3.0, 32));
  const OwnedTexture water(postfxtest::makeWaterTexture(16, 3, 0.02));
  const OwnedTexture good(makeRegionTexture(16, {4.0, 4.0}, flatSurface));
  const OwnedTexture wrongFormat([] {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, 1, GL_RGBA8, 16, 16);
    return t;
  }());
  auto fx = postfxtest::makeContext(kLocal);
  auto featureless = postfxtest::makeContext(postfxtest::kRaw);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    const char* field;
    std::function<void(postfx::FrameDesc&, postfx::LocalWater&)> spoil;
    bool withoutFeature = false;
  };
  const Case cases[] = {
      {"localWaterCount",
       [](postfx::FrameDesc& f, postfx::LocalWater&) { f.water.localWaterCount = 5; }},
      {"localWaterCount",
       [](postfx::FrameDesc& f, postfx::LocalWater&) { f.water.localWaterCount = -1; }},
      {"water.localWater is null",
       [](postfx::FrameDesc& f, postfx::LocalWater&) { f.water.localWater = nullptr; }},
      {"Feature::LocalWater", [](postfx::FrameDesc&, postfx::LocalWater&) {}, true},
      {"centre", [nan](postfx::FrameDesc&, postfx::LocalWater& r) { r.centre.x = nan; }},
      {"centre", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.centre.y = 2e9; }},
      {"size", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.size.x = 0.0; }},
      {"size", [nan](postfx::FrameDesc&, postfx::LocalWater& r) { r.size.y = nan; }},
      {"rotation", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.rotation = INFINITY; }},
      {"mode",
       [](postfx::FrameDesc&, postfx::LocalWater& r) { r.mode = postfx::LocalWaterMode(7); }},
      {"edgeBlend", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.edgeBlend = 2.5f; }},
      {"edgeBlend", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.edgeBlend = -0.1f; }},
      {"gridResolution", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.gridResolution = 8; }},
      {"depthLayers", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.depthLayers = 9; }},
      {"maxDepth", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.maxDepth = 0.0f; }},
      {"texture", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.texture.texture = 0; }},
      {"texture",
       [&wrongFormat](postfx::FrameDesc&, postfx::LocalWater& r) {
         r.texture = {GLuint(wrongFormat), 0};
       }},
      {"texture", [](postfx::FrameDesc&, postfx::LocalWater& r) { r.texture.format = GL_RG16F; }},
  };
  const glm::vec4 marker(0.25f, 0.5f, 0.75f, 1.0f);
  for (const Case& c : cases) {
    SCOPED_TRACE(c.field);
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
    postfx::LocalWater r = region(good, {0.0, 0.0}, {4.0, 4.0}, postfx::LocalWaterMode::Add, 3.0f);
    frame.water.localWater = &r;
    frame.water.localWaterCount = 1;
    c.spoil(frame, r);
    postfx::Context& context = c.withoutFeature ? *featureless : *fx;
    scene.clearTarget(marker);
    const postfx::Result result = postfx::dispatch(context, frame);
    EXPECT_NE(result, postfx::Result::Ok);
    EXPECT_NE(std::string(postfx::lastError(&context)).find(c.field), std::string::npos)
        << postfx::lastError(&context);
    for (const glm::vec4& p : target(scene))
      ASSERT_EQ(p, marker) << "a refused frame draws nothing";
  }
}

// A broken simulation (NaN, infinite and huge heights and slopes in its texture) lights its
// region as flat water, never NaN: the grid sanitises the surface as the cascades' lookups do.
TEST_F(PostfxLocalWaterTest, BrokenRegionTexturesStayFinite) {
  Scene scene(downSpec(3.0, 64));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(32, 3, 0.02));
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Surface broken = [&](glm::dvec2 p) {
    const int cell = int(std::floor(p.x * 4.0)) + 3 * int(std::floor(p.y * 4.0));
    switch (((cell % 4) + 4) % 4) {
      case 0:
        return glm::dvec3(nan, 0.1, nan);
      case 1:
        return glm::dvec3(inf, -inf, 1e30);
      case 2:
        return glm::dvec3(1e9, 0.0, -1e9);
      default:
        return rippledSurface(p);
    }
  };
  const OwnedTexture surface(makeRegionTexture(64, {6.0, 6.0}, broken));
  auto fx = postfxtest::makeContext(kLocal | postfx::Feature::GodRays);
  for (const postfx::LocalWaterMode mode :
       {postfx::LocalWaterMode::Replace, postfx::LocalWaterMode::Add}) {
    SCOPED_TRACE(int(mode));
    postfx::FrameDesc frame = postfxtest::makeFrame(scene, stormy, 3);
    const postfx::LocalWater pool = region(surface, {0.0, 0.0}, {6.0, 6.0}, mode, 3.0f);
    frame.water.localWater = &pool;
    frame.water.localWaterCount = 1;
    const Drawn drawn = draw(*fx, scene, frame);
    int lit = 0;
    for (const glm::vec4& p : drawn.target) {
      ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b));
      lit += p.g > 0.0f;
    }
    for (float r : drawn.raw) ASSERT_TRUE(std::isfinite(r) && r >= 0.0f);
    EXPECT_GT(lit, 1000) << "the broken texels light as flat water, not as nothing";
  }
}

// The god rays read the regions' light as the seabed does: a flat Replace region over the whole
// view turns a stormy sea's shafts into flat water's.
TEST_F(PostfxLocalWaterTest, GodRaysReadTheRegionsLight) {
  SceneSpec spec = downSpec(6.0, 64, -1.0);
  spec.lookDirection = glm::dvec3(0.0, -0.5, -1.0);
  Scene scene(spec);
  const OwnedTexture calm(postfxtest::makeWaterTexture(32, 3, 0.0));
  const OwnedTexture stormy(postfxtest::makeWaterTexture(64, 3, 0.05));
  const OwnedTexture flat(makeRegionTexture(16, {400.0, 400.0}, flatSurface));
  auto fx = postfxtest::makeContext(kLocal | postfx::Feature::GodRays);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, calm, 3);
  frame.caustics.enabled = false;  // the shafts alone
  frame.godRays.maxDistance = 40.0f;
  const Drawn reference = draw(*fx, scene, frame);
  frame.water.texture.texture = stormy;
  const Drawn sea = draw(*fx, scene, frame);
  postfx::LocalWater pool =
      region(flat, {0.0, 0.0}, {400.0, 400.0}, postfx::LocalWaterMode::Replace, 60.0f);
  pool.gridResolution = 64;
  frame.water.localWater = &pool;
  frame.water.localWaterCount = 1;
  const Drawn pooled = draw(*fx, scene, frame);
  double worst = 0.0, seaDeparture = 0.0, largest = 0.0;
  for (std::size_t i = 0; i < reference.target.size(); ++i) {
    largest = std::max(largest, double(reference.target[i].g));
    worst = std::max(worst, double(std::abs(pooled.target[i].g - reference.target[i].g)));
    seaDeparture =
        std::max(seaDeparture, double(std::abs(sea.target[i].g - reference.target[i].g)));
  }
  std::printf("shafts up to %.4f: flat region vs flat water %.2e, the sea departs %.2e\n", largest,
              worst, seaDeparture);
  ASSERT_GT(largest, 0.0);
  EXPECT_GT(seaDeparture, 0.05 * largest);
  EXPECT_LT(worst, 0.01 * largest);
}

// The estimate a frame is refused by is, byte for byte, what the regions hold afterwards; a
// frame without regions holds nothing of theirs.
TEST_F(PostfxLocalWaterTest, MemoryEstimateIsWhatIsAllocated) {
  Scene scene(downSpec(3.0, 32));
  const OwnedTexture water(postfxtest::makeWaterTexture(16, 3, 0.02));
  const OwnedTexture surface(makeRegionTexture(16, {4.0, 4.0}, rippledSurface));
  auto fx = postfxtest::makeContext(kLocal);
  postfx::FrameDesc frame = postfxtest::makeFrame(scene, water, 3);
  postfx::LocalWater regions[2] = {
      region(surface, {0.0, 0.0}, {4.0, 4.0}, postfx::LocalWaterMode::Add, 3.0f),
      region(surface, {2.0, 1.0}, {3.0, 5.0}, postfx::LocalWaterMode::Replace, 2.0f)};
  regions[1].gridResolution = 200;
  regions[1].depthLayers = 3;
  frame.water.localWater = regions;
  for (int count : {2, 1, 0}) {
    SCOPED_TRACE(count);
    frame.water.localWaterCount = count;
    ASSERT_EQ(postfx::dispatch(*fx, frame), postfx::Result::Ok) << postfx::lastError(fx.get());
    EXPECT_EQ(postfx::detail::localWaterBytes(frame), fx->localWater.allocatedBytes());
  }
  EXPECT_EQ(fx->localWater.allocatedBytes(), 0u);
}

}  // namespace
