// Object caustics contracts: nothing to do costs nothing, bad input fails cleanly with the host's
// GL state untouched, extreme cases stay finite and conserve energy, the composite adds exactly
// the map's light on receivers only, and the temporal filter leaves no trail.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "gl_fixture.h"
#include "postfx_gl_snapshot.h"
#include "postfx_host_state.h"
#include "postfx_object_caustics_util.h"

namespace {

using namespace postfxtest;
using postfx::Result;

void expectSameState(const GlSnapshot& before, const GlSnapshot& after, const std::string& when) {
  for (const auto& [name, value] : before) {
    auto it = after.find(name);
    ASSERT_NE(it, after.end()) << name;
    EXPECT_EQ(value, it->second) << when << ": GL state '" << name << "' changed";
  }
}

postfx::CasterMaterial glass(float ior = 1.5f) {
  postfx::CasterMaterial m;
  m.ior = ior;
  return m;
}

class PostfxObjectCausticsContractTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    host_.reset();
    testsupport::GlTest::TearDown();
  }
  HostState host_;
};

TEST_F(PostfxObjectCausticsContractTest, NoCasterIsSkippedAtZeroCost) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  auto fx = makeObjectContext();
  ASSERT_TRUE(postfx::stats(*fx).pass(postfx::Pass::ObjectCaustics).present);
  host.scene.clearTarget(glm::vec4(0.25f));
  postfx::ObjectCausticsSettings s;
  // No casters, then a caster outside the receiver map's view, then the pass switched off.
  const postfx::CasterMesh far = mesh.caster(translation({500.0, 1.5, 0.0}), glass());
  const postfx::CasterMesh near = mesh.caster(translation({0.0, 1.5, 0.0}), glass());
  std::vector<std::function<postfx::FrameDesc()>> frames = {
      [&] { return host.frame(nullptr, 0, s); }, [&] { return host.frame(&far, 1, s); },
      [&] {
        postfx::ObjectCausticsSettings off = s;
        off.enabled = false;
        return host.frame(&near, 1, off);
      }};
  for (auto& make : frames) {
    for (int i = 0; i < 6; ++i) ASSERT_EQ(postfx::dispatch(*fx, make()), Result::Ok);
    glFinish();
    ASSERT_EQ(postfx::dispatch(*fx, make()), Result::Ok);
  }
  const postfx::PassStats& p = postfx::stats(*fx).pass(postfx::Pass::ObjectCaustics);
  std::printf("skipped: lastMs %.6f medianMs %.6f samples %u skipped %d\n", p.lastMs, p.medianMs,
              p.samples, int(p.skipped));
  EXPECT_TRUE(p.skipped);
  EXPECT_EQ(p.lastMs, 0.0);
  EXPECT_EQ(p.medianMs, 0.0);
  EXPECT_GT(p.samples, 0u);
  EXPECT_EQ(postfx::objectCausticMap(*fx).texture, 0u) << "the pass never ran";
  for (const glm::vec4& v :
       readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
    ASSERT_EQ(v, glm::vec4(0.25f));

  // And the caster in view does run it (the test can fail).
  for (int i = 0; i < 6; ++i) ASSERT_EQ(postfx::dispatch(*fx, host.frame(&near, 1, s)), Result::Ok);
  glFinish();
  ASSERT_EQ(postfx::dispatch(*fx, host.frame(&near, 1, s)), Result::Ok);
  std::printf("running: lastMs %.3f\n", p.lastMs);
  EXPECT_FALSE(p.skipped);
  EXPECT_GT(p.lastMs, 0.0);
}

TEST_F(PostfxObjectCausticsContractTest, BadInputFailsCleanly) {
  ObjectHost host(sunAt(20.0, 0.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  auto fx = makeObjectContext();
  GLint maxTexture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxTexture);
  GLuint notBuffer = 0;
  glGenBuffers(1, &notBuffer);  // a name, never a buffer
  const double nan = std::numeric_limits<double>::quiet_NaN();
  struct Case {
    const char* name;
    Result expected;
    const char* mentions;
    std::function<void(postfx::CasterMesh&, postfx::FrameDesc&)> spoil;
  };
  const Case cases[] = {
      {"no triangles", Result::InvalidArgument, "no triangles",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.indexCount = 2; }},
      {"NaN transform", Result::InvalidArgument, "modelToWorld",
       [nan](postfx::CasterMesh& m, postfx::FrameDesc&) { m.modelToWorld[3][1] = nan; }},
      {"singular transform", Result::InvalidArgument, "invertible",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.modelToWorld[1] = glm::dvec4(0.0); }},
      {"IOR below 1", Result::InvalidArgument, "ior",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.material.ior = 0.9f; }},
      {"absurd IOR", Result::InvalidArgument, "ior",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.material.ior = 40.0f; }},
      {"NaN IOR", Result::InvalidArgument, "ior",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.material.ior = float(NAN); }},
      {"negative absorption", Result::InvalidArgument, "absorption",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.material.absorption.g = -1.0f; }},
      {"map size 0", Result::InvalidArgument, "mapSize",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) { f.objectCaustics.settings.mapSize = 0; }},
      {"map size beyond GL", Result::InvalidArgument, "GL_MAX_TEXTURE_SIZE",
       [maxTexture](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.objectCaustics.settings.mapSize = maxTexture * 2;
       }},
      {"grid size 0", Result::InvalidArgument, "gridSize",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) { f.objectCaustics.settings.gridSize = 0; }},
      {"iterations 0", Result::InvalidArgument, "iterations",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) { f.objectCaustics.settings.iterations = 0; }},
      {"splat radius NaN", Result::InvalidArgument, "splatRadius",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.objectCaustics.settings.splatRadius = float(NAN);
       }},
      {"vertex buffer not a buffer", Result::MissingTexture, "vertexBuffer",
       [notBuffer](postfx::CasterMesh& m, postfx::FrameDesc&) { m.vertexBuffer = notBuffer; }},
      {"buffer too small", Result::SizeMismatch, "vertexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.vertexCount *= 4; }},
      // Sizes and offsets that overflow 64-bit arithmetic if multiplied or added naively: the
      // first drew 1.4e9 vertices from an 864-byte buffer, INT64_MAX counts raised GL errors
      // after Ok, and a huge base offset dropped the caster silently.
      {"vertex count whose byte size wraps", Result::InvalidArgument, "vertexCount",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.vertexCount = 384307168202282566; }},
      {"vertex count INT64_MAX", Result::InvalidArgument, "vertexCount",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.vertexCount = std::numeric_limits<std::int64_t>::max();
       }},
      {"vertex count just past GLsizei", Result::InvalidArgument, "vertexCount",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.vertexCount = (1ll << 31); }},
      {"non-indexed, 2^31 - 1 vertices", Result::SizeMismatch, "vertexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.indexBuffer = 0;
         m.vertexCount = (1ll << 31) - 1;
         m.stride = 2048;
       }},
      {"index count INT64_MAX", Result::InvalidArgument, "indexCount",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.indexCount = std::numeric_limits<std::int64_t>::max();
       }},
      {"index count 2^62", Result::InvalidArgument, "indexCount",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.indexCount = 1ll << 62; }},
      {"base offset INT64_MAX", Result::SizeMismatch, "vertexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.baseOffset = std::numeric_limits<std::int64_t>::max();
       }},
      {"base offset that wraps the end negative", Result::SizeMismatch, "vertexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.baseOffset = std::numeric_limits<std::int64_t>::max() - 100;
       }},
      {"base offset one vertex past the end", Result::SizeMismatch, "vertexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.baseOffset = m.stride; }},
      {"index offset INT64_MAX - 3", Result::SizeMismatch, "indexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.indexOffset = std::numeric_limits<std::int64_t>::max() - 3;
       }},
      {"normal read past the buffer's end", Result::SizeMismatch, "vertexBuffer",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         // Positions at the end of each record, normals first: the normal of the last vertex
         // fits only if the buffer is read from 12 bytes further on.
         m.baseOffset = 12;
         m.positionOffset = 0;
         m.normalOffset = 12;
       }},
      // Positions and transforms whose floats would overflow: the composite once wrote NaN
      // into 1320 target values with water.level 1e300 and no absorption.
      {"water level 1e300", Result::InvalidArgument, "water.level",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.water.level = 1e300;
         f.water.absorption = glm::vec3(0.0f);
       }},
      {"caster 1e12 m out", Result::InvalidArgument, "world bounds",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.modelToWorld[3][0] = 1e12; }},
      {"caster scaled by 1e300 around empty bounds", Result::InvalidArgument, "modelToWorld",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.boundsMin = m.boundsMax = glm::vec3(0.0f);
         m.modelToWorld[0][0] = m.modelToWorld[1][1] = m.modelToWorld[2][2] = 1e300;
       }},
      {"index type", Result::InvalidArgument, "indexType",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) {
         m.indexType = static_cast<postfx::IndexType>(GL_FLOAT);
       }},
      {"stride too small", Result::InvalidArgument, "stride",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.stride = 8; }},
      {"bounds inverted", Result::InvalidArgument, "bounds",
       [](postfx::CasterMesh& m, postfx::FrameDesc&) { m.boundsMin.x = 5.0f; }},
      {"too many casters", Result::InvalidArgument, "casterCount",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.objectCaustics.casterCount = postfx::kMaxCasters + 1;
       }},
      {"null casters", Result::InvalidArgument, "null",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) { f.objectCaustics.casters = nullptr; }},
      {"receiver depth missing", Result::MissingTexture, "receivers",
       [](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.objectCaustics.receivers.depth.texture = 0;
       }},
      {"receiver not a depth format", Result::UnsupportedFormat, "receivers",
       [&host](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.objectCaustics.receivers.depth = {host.scene.target, 0};
       }},
      {"receiver matrix NaN", Result::InvalidArgument, "worldToLightClip",
       [nan](postfx::CasterMesh&, postfx::FrameDesc& f) {
         f.objectCaustics.receivers.worldToLightClip[0][0] = nan;
       }},
  };
  host.scene.clearTarget(glm::vec4(0.5f));
  for (const Case& c : cases) {
    postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.5, 0.0}), glass());
    postfx::FrameDesc frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
    c.spoil(caster, frame);
    host_.set();
    const GlSnapshot before = snapshotGlState();
    const Result r = postfx::dispatch(*fx, frame);
    const std::string message = postfx::lastError(fx.get());
    std::printf("%-28s -> %s: %s\n", c.name, postfx::toString(r), message.c_str());
    EXPECT_EQ(r, c.expected) << c.name;
    EXPECT_NE(message.find(c.mentions), std::string::npos) << c.name << ": " << message;
    expectSameState(before, snapshotGlState(), c.name);
    host_.reset();
  }
  for (const glm::vec4& v :
       readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
    ASSERT_EQ(v, glm::vec4(0.5f)) << "nothing drawn";
  EXPECT_EQ(postfx::objectCausticMap(*fx).texture, 0u);
  glDeleteBuffers(1, &notBuffer);
}

// A map the budget cannot hold is refused before any pass adds light: mapSize 16384 (documented
// valid) once ran out of memory after the seabed caustics and god rays had been added, and 8192
// took 30 s and 9.6 GB before returning Ok.
TEST_F(PostfxObjectCausticsContractTest, SettingsOverTheMemoryBudgetAreRefusedUpFront) {
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 32, 16);
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.5, 0.0}), glass());
  auto fx = makeContext(postfx::Feature::ObjectCaustics | postfx::Feature::Caustics |
                        postfx::Feature::GodRays);
  postfx::FrameDesc frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
  frame.water.level = 10.0;  // everything under water: every pass has work
  const int w = host.scene.spec().width, h = host.scene.spec().height;
  const glm::vec4 marker(0.25f);
  host.scene.clearTarget(marker);
  ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
  const postfx::FrameStats& stats = postfx::stats(*fx);
  for (int p = 0; p < postfx::kPassCount; ++p) {
    if (stats.passes[p].present) {
      EXPECT_FALSE(stats.passes[p].skipped)
          << postfx::toString(postfx::Pass(p)) << ": every pass ran";
    }
  }
  int changed = 0;
  for (const glm::vec4& v : readRgba(host.scene.target, w, h)) changed += v != marker ? 1 : 0;
  EXPECT_GT(changed, 100) << "the frame within budget adds light (the test can tell)";

  for (int mapSize : {8192, 16384}) {
    SCOPED_TRACE(mapSize);
    frame.objectCaustics.settings.mapSize = mapSize;
    host.scene.clearTarget(marker);
    EXPECT_EQ(postfx::dispatch(*fx, frame), Result::OutOfMemory);
    const std::string message = postfx::lastError(fx.get());
    EXPECT_NE(message.find("mapSize"), std::string::npos) << message;
    EXPECT_NE(message.find("memoryBudgetMiB"), std::string::npos) << message;
    for (const glm::vec4& v : readRgba(host.scene.target, w, h))
      ASSERT_EQ(v, marker) << "nothing added before the refusal";
  }

  // The budget is the host's: the default map (12 MiB) and caster maps (5.3 MiB: positions,
  // normals, depth and where each ray lands) do not fit 8.
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::ObjectCaustics;
  desc.memoryBudgetMiB = 8;
  postfx::Context* raw = nullptr;
  ASSERT_EQ(postfx::create(desc, raw), Result::Ok) << postfx::lastError(nullptr);
  ContextPtr small(raw);
  frame = host.frame(&caster, 1, postfx::ObjectCausticsSettings{});
  EXPECT_EQ(postfx::dispatch(*small, frame), Result::OutOfMemory);
  frame.objectCaustics.settings.mapSize = 128;  // 0.75 MiB + 5.3 MiB
  EXPECT_EQ(postfx::dispatch(*small, frame), Result::Ok) << postfx::lastError(small.get());
  desc.memoryBudgetMiB = 0;
  EXPECT_EQ(postfx::create(desc, raw), Result::InvalidArgument);
  EXPECT_NE(std::string(postfx::lastError(nullptr)).find("memoryBudgetMiB"), std::string::npos);
}

TEST_F(PostfxObjectCausticsContractTest, HostStateSurvivesThePass) {
  ObjectHost host(sunAt(20.0, 30.0));
  const GlMesh mesh = makeSphereMesh(1.0, 48, 24);
  postfx::Context* raw = nullptr;
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::ObjectCaustics | postfx::Feature::Caustics |
                  postfx::Feature::GodRays | postfx::testing::BenchmarkFloor;
  host_.set();
  GlSnapshot before = snapshotGlState();
  ASSERT_EQ(postfx::create(desc, raw), Result::Ok) << postfx::lastError(nullptr);
  ContextPtr fx(raw);
  expectSameState(before, snapshotGlState(), "create");
  const postfx::CasterMesh caster = mesh.caster(translation({0.2, 1.5, 0.1}), glass());
  postfx::ObjectCausticsSettings s;
  s.temporalFilter = true;
  postfx::FrameDesc frame = host.frame(&caster, 1, s);
  frame.water.level = 10.0;  // seabed caustics and god rays run too
  for (int i = 0; i < 2; ++i) {
    ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
    expectSameState(before, snapshotGlState(), "dispatch with object caustics");
  }
  host_.reset();
  EXPECT_NE(postfx::objectCausticMap(*fx).texture, 0u);
}

// Map and target stay finite, the map non-negative, and no more light leaves than the caster
// intercepts (its sun-perpendicular bounding area).
void expectSane(postfx::Context& fx, const ObjectHost& host, const char* name,
                double interceptBound) {
  const postfx::ObjectCausticMap map = postfx::objectCausticMap(fx);
  ASSERT_NE(map.texture, 0u) << name;
  const std::vector<glm::dvec3> values = readObjectMap(map);
  double lowest = 0.0;
  for (const glm::dvec3& v : values) lowest = std::min({lowest, v.r, v.g, v.b});
  const glm::dvec3 flux = mapFlux(values, map);
  bool targetFinite = true;
  for (const glm::vec4& v :
       readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
    targetFinite = targetFinite && std::isfinite(v.r) && std::isfinite(v.g) && std::isfinite(v.b);
  std::printf("%-30s map finite %d, lowest %.3g, flux %.4f m^2 (bound %.4f), target finite %d\n",
              name, int(allFinite(values)), lowest, flux.g, interceptBound, int(targetFinite));
  EXPECT_TRUE(allFinite(values)) << name;
  EXPECT_GE(lowest, 0.0) << name;
  EXPECT_LE(flux.g, interceptBound * 1.02) << name;
  EXPECT_TRUE(targetFinite) << name;
}

TEST_F(PostfxObjectCausticsContractTest, ExtremeCasesStayFinite) {
  auto fx = makeObjectContext();
  postfx::ObjectCausticsSettings s;
  s.gridSize = 128;
  s.mapSize = 256;
  s.iterations = 5;
  const GlMesh sphere = makeSphereMesh(1.0, 64, 32);
  {  // grazing light: 2 degrees above the horizon
    ObjectHost host(sunAt(88.0, 10.0), 30.0);
    const postfx::CasterMesh c = sphere.caster(translation({0.0, 1.5, 0.0}), glass());
    ASSERT_EQ(postfx::dispatch(*fx, host.frame(&c, 1, s)), Result::Ok)
        << postfx::lastError(fx.get());
    expectSane(*fx, host, "grazing light", kPi);
  }
  {  // the sphere resting on the receiver
    ObjectHost host(sunAt(10.0, 0.0));
    const postfx::CasterMesh c = sphere.caster(translation({0.0, 1.0, 0.0}), glass());
    ASSERT_EQ(postfx::dispatch(*fx, host.frame(&c, 1, s)), Result::Ok);
    expectSane(*fx, host, "touching the receiver", kPi);
  }
  {  // a caster far larger than the receiver map's view (radius 20 m, map +-4 m)
    ObjectHost host(sunAt(15.0, 0.0), 4.0);
    glm::dmat4 big = translation({0.0, 22.0, 0.0});
    big = glm::scale(big, glm::dvec3(20.0));
    const postfx::CasterMesh c = sphere.caster(big, glass());
    ASSERT_EQ(postfx::dispatch(*fx, host.frame(&c, 1, s)), Result::Ok);
    expectSane(*fx, host, "caster larger than the view", kPi * 400.0);
  }
  {  // degenerate mesh: every vertex at one point, zero normals
    ObjectHost host(sunAt(10.0, 0.0));
    const GlMesh point({glm::vec3(0.5f), glm::vec3(0.5f), glm::vec3(0.5f)},
                       {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)}, {0, 1, 2});
    const postfx::CasterMesh c = point.caster(translation({0.0, 1.0, 0.0}), glass());
    ASSERT_EQ(postfx::dispatch(*fx, host.frame(&c, 1, s)), Result::Ok);
    expectSane(*fx, host, "degenerate mesh", 1e-3);
  }
  {  // total internal reflection: a dense tilted glass cube with flat (derived) normals
    ObjectHost host(sunAt(50.0, 0.0));
    const GlMesh cube = makeCubeMesh(0.5);
    glm::dmat4 m = translation({0.0, 1.2, 0.0});
    m = glm::rotate(m, 0.6, glm::dvec3(0.3, 0.2, 1.0));
    postfx::CasterMesh c = cube.caster(m, glass(2.8f));
    c.normalOffset = -1;
    ASSERT_EQ(postfx::dispatch(*fx, host.frame(&c, 1, s)), Result::Ok);
    expectSane(*fx, host, "total internal reflection", 3.0 * 1.0);
  }
}

TEST_F(PostfxObjectCausticsContractTest, CompositeAddsTheMapOnReceiversOnly) {
  // The host G-buffer: the plane y = 0 with a step down to y = -0.5 for x > 1.5 (not in the
  // receiver map: must get nothing) and the glass sphere itself (not a receiver: nothing).
  SceneSpec spec = ObjectHost::defaultSpec();
  const glm::dvec3 centre(0.2, 1.5, -1.0);
  spec.stepX = 1.5;
  spec.floorY2 = -0.5;
  spec.sphere = true;
  spec.sphereCenter = centre - spec.camera;
  spec.sphereRadius = 1.0;
  const glm::dvec3 sun = sunAt(20.0, 30.0);
  ObjectHost host(sun, 4.0, spec);
  const GlMesh mesh = makeSphereMesh(1.0, 96, 48);
  const postfx::CasterMesh caster = mesh.caster(translation(centre), glass());
  auto fx = makeObjectContext();
  postfx::ObjectCausticsSettings s;
  s.iterations = 3;
  const postfx::FrameDesc frame = host.frame(&caster, 1, s);
  ASSERT_EQ(postfx::dispatch(*fx, frame), Result::Ok) << postfx::lastError(fx.get());
  const postfx::ObjectCausticMap map = postfx::objectCausticMap(*fx);
  const std::vector<glm::dvec3> values = readObjectMap(map);
  const int w = spec.width, h = spec.height;
  const std::vector<glm::vec4> target = readRgba(host.scene.target, w, h);
  // Expected: E * albedo * caustic(bilinear at the pixel's light-space position) * N.L.
  auto bilinear = [&](const glm::dvec3& p) {
    const double u2 = glm::dot(map.axisU, map.axisU), v2 = glm::dot(map.axisV, map.axisV);
    const double tx = glm::dot(p - map.origin, map.axisU) / u2 * map.size - 0.5;
    const double ty = glm::dot(p - map.origin, map.axisV) / v2 * map.size - 0.5;
    const int x0 = int(std::floor(tx)), y0 = int(std::floor(ty));
    const double ax = tx - x0, ay = ty - y0;
    auto at = [&](int x, int y) {
      x = std::clamp(x, 0, map.size - 1);
      y = std::clamp(y, 0, map.size - 1);
      return values[y * map.size + x].g;
    };
    return (1 - ay) * ((1 - ax) * at(x0, y0) + ax * at(x0 + 1, y0)) +
           ay * ((1 - ax) * at(x0, y0 + 1) + ax * at(x0 + 1, y0 + 1));
  };
  double sumError = 0.0, sumExpected = 0.0, offReceiver = 0.0, peak = 0.0;
  int compared = 0, offCount = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const PixelTruth& t = host.scene.truth(x, y);
      const double got = target[y * w + x].g;
      if (t.hit == Hit::Sky) continue;
      const glm::dvec3 world = t.position + spec.camera;
      if (t.hit == Hit::Sphere || world.y < -0.25) {
        offReceiver = std::max(offReceiver, std::abs(got));
        ++offCount;
        continue;
      }
      const double expected = 2.0 * bilinear(world) * glm::dot(t.normal, sun);
      peak = std::max(peak, expected);
      sumError += std::abs(got - expected);
      sumExpected += expected;
      ++compared;
    }
  }
  std::printf(
      "composite: %d receiver pixels, mean |error| / mean light %.4f, peak %.3f; %d "
      "off-receiver pixels, largest light there %.3g\n",
      compared, sumError / std::max(sumExpected, 1e-30), peak, offCount, offReceiver);
  EXPECT_GT(peak, 2.0) << "the focus is in view";
  EXPECT_LT(sumError / sumExpected, 0.02);
  EXPECT_GT(offCount, 100);
  EXPECT_EQ(offReceiver, 0.0);
}

TEST_F(PostfxObjectCausticsContractTest, TemporalFilterConvergesAndLeavesNoTrail) {
  ObjectHost host(sunAt(20.0, 0.0));
  ObjectHost lowered(sunAt(20.0, 0.0));  // the same receivers moved: see below
  const GlMesh mesh = makeSphereMesh(1.0, 64, 32);
  const postfx::CasterMesh caster = mesh.caster(translation({0.0, 1.5, 0.0}), glass());
  auto plain = makeObjectContext();
  auto filtered = makeObjectContext();
  postfx::ObjectCausticsSettings s;
  s.gridSize = 128;
  s.mapSize = 256;
  s.iterations = 3;
  postfx::ObjectCausticsSettings t = s;
  t.temporalFilter = true;
  t.temporalWeight = 0.9f;
  for (int i = 0; i < 3; ++i) {
    ASSERT_EQ(postfx::dispatch(*filtered, host.frame(&caster, 1, t)), Result::Ok);
  }
  ASSERT_EQ(postfx::dispatch(*plain, host.frame(&caster, 1, s)), Result::Ok);
  std::vector<glm::dvec3> a = readObjectMap(postfx::objectCausticMap(*plain));
  std::vector<glm::dvec3> b = readObjectMap(postfx::objectCausticMap(*filtered));
  double staticDiff = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    staticDiff = std::max(staticDiff, std::abs(a[i].g - b[i].g));
  // Move the receiver 0.6 m down (same sun view: the map stays put, the caustic changes).
  ReceiverMap deeper(host.towardSun, glm::dvec3(0.0), 4.0, -0.6, 1024);
  postfx::FrameDesc moved = host.frame(&caster, 1, t);
  moved.objectCaustics.receivers = deeper.desc();
  ASSERT_EQ(postfx::dispatch(*filtered, moved), Result::Ok);
  postfx::FrameDesc movedPlain = host.frame(&caster, 1, s);
  movedPlain.objectCaustics.receivers = deeper.desc();
  ASSERT_EQ(postfx::dispatch(*plain, movedPlain), Result::Ok);
  a = readObjectMap(postfx::objectCausticMap(*plain));
  b = readObjectMap(postfx::objectCausticMap(*filtered));
  // Ghost: light the filtered map keeps where this frame's splats have none in a 3x3 window.
  const int n = postfx::objectCausticMap(*plain).size;
  double ghost = 0.0, oldPeak = 0.0, filteredDiff = 0.0;
  for (size_t i = 0; i < a.size(); ++i)
    filteredDiff = std::max(filteredDiff, std::abs(a[i].g - b[i].g));
  for (int y = 1; y < n - 1; ++y)
    for (int x = 1; x < n - 1; ++x) {
      double hi = 0.0;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) hi = std::max(hi, a[(y + j) * n + x + i].g);
      ghost = std::max(ghost, b[y * n + x].g - hi);
      oldPeak = std::max(oldPeak, b[y * n + x].g);
    }
  std::printf(
      "temporal: static max |filtered - plain| %.3g; after the receiver moved, max "
      "|filtered - plain| %.3g, light above the new 3x3 maximum %.3g (map peak %.3f)\n",
      staticDiff, filteredDiff, ghost, oldPeak);
  EXPECT_GT(filteredDiff, 1e-3) << "the history must still be blended in";
  EXPECT_LT(staticDiff, 1e-4);
  EXPECT_LE(ghost, 1e-6);
}

}  // namespace
