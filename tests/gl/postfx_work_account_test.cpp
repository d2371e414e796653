// The work account (CreateDesc::workAccount, postfx/diagnostics.h): its counts are what the
// algorithm says they are, they move with the settings as it says, a feature off counts 0, and
// each shader's stated fetches and atomics per invocation (docs/gpu_cost.md) are what its own
// instrumented copy counts (testing::CountShaderWork) on the full path, and never less
// elsewhere.
#include <gtest/gtest.h>
#include <postfx/testing.h>

#include <string>
#include <vector>

#include "gl_fixture.h"
#include "postfx_host_state.h"
#include "postfx_scene.h"
#include "postfx_test_util.h"

namespace {

using postfx::Feature;
using postfx::Pass;

class PostfxWorkAccountTest : public testsupport::GlTest {
 protected:
  void TearDown() override {
    if (water_ != 0) glDeleteTextures(1, &water_);
    testsupport::GlTest::TearDown();
  }
  GLuint water(int cascades = 3) {
    if (water_ == 0) water_ = postfxtest::makeWaterTexture(64, cascades, 0.02);
    return water_;
  }
  GLuint water_ = 0;
};

postfxtest::ContextPtr makeAccountingContext(Feature features, bool counted, bool account = true) {
  postfx::CreateDesc desc;
  desc.features = counted ? features | postfx::testing::CountShaderWork : features;
  desc.workAccount = account;
  postfx::Context* fx = nullptr;
  EXPECT_EQ(postfx::create(desc, fx), postfx::Result::Ok) << postfx::lastError(nullptr);
  return postfxtest::ContextPtr(fx);
}

// Dispatches `frame` until its queries have been read back (the same frame every time).
void dispatchResolved(postfx::Context& fx, const postfx::FrameDesc& frame) {
  for (int i = 0; i < postfx::kTimerRingDepth + 1; ++i) {
    ASSERT_EQ(postfx::dispatch(fx, frame), postfx::Result::Ok) << postfx::lastError(&fx);
    glFinish();
  }
  ASSERT_GT(postfx::stats(fx).framesResolved, 0u);
}

// The sum of every step called `name` in the last resolved frame (a pass's per-cascade or
// per-layer calls), and how many there were.
struct Summed {
  postfx::WorkStep step;
  int calls = 0;
};
Summed summed(const postfx::Context& fx, const std::string& name) {
  Summed out;
  const postfx::WorkSteps steps = postfx::workSteps(fx);
  for (int i = 0; i < steps.count; ++i) {
    const postfx::WorkStep& s = steps.steps[i];
    if (name != s.name) continue;
    if (out.calls++ == 0) {
      out.step = s;
    } else {
      out.step.work += s.work;
      out.step.statedFetches += s.statedFetches;
      out.step.statedAtomics += s.statedAtomics;
    }
  }
  return out;
}

// A seabed under the water filling the view, seen from above it: every pixel under the water,
// facing the sun, unshadowed. Near: 3 m below the camera seen steeply, every pixel's footprint
// fine enough for every cascade. Deep: 36 m below, seen at 35 degrees down, every god-ray march
// long and slanted enough to cross all its samples' planes.
postfxtest::SceneSpec fullPathSpec(bool deep = false) {
  postfxtest::SceneSpec spec;
  spec.width = 96;
  spec.height = 54;
  spec.camera = {0.0, -4.0, 0.0};
  spec.lookDirection = deep ? glm::dvec3(0.0, -0.7, -1.0) : glm::dvec3(0.0, -1.0, -0.6);
  spec.floorY = deep ? -40.0 : -7.0;
  spec.sphere = false;
  return spec;
}

postfx::FrameDesc fullPathFrame(const postfxtest::Scene& scene, GLuint water) {
  postfx::FrameDesc f = postfxtest::makeFrame(scene, water, 3);
  f.caustics.minCascadeContrast = 0.0f;  // every cascade everywhere: the lookups' full path
  f.godRays.maxDistance = 100.0f;
  return f;
}

TEST_F(PostfxWorkAccountTest, FullScreenPassCountsOneFragmentPerPixel) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics | postfx::testing::BenchmarkFloor, true);
  dispatchResolved(*fx, fullPathFrame(scene, water()));
  const Summed floor = summed(*fx, "floor.inputs");
  ASSERT_EQ(floor.calls, 1);
  const std::uint64_t pixels = 96 * 54;
  EXPECT_EQ(floor.step.work.fragments, pixels);
  EXPECT_EQ(floor.step.work.samplesPassed, pixels);
  EXPECT_EQ(floor.step.work.draws, 1u);
  EXPECT_EQ(floor.step.work.primitivesSubmitted, 1u);
  EXPECT_EQ(floor.step.targetBytes, 8);  // the RGBA16F target
  EXPECT_TRUE(floor.step.blended);
  EXPECT_NE(floor.step.work.sources & postfx::kWorkCounted, 0u);
  // Blended: every sample written is read first.
  EXPECT_EQ(floor.step.work.blendedSamples, pixels);
  EXPECT_GE(floor.step.work.bytesWritten, pixels * 8);
  EXPECT_GE(floor.step.work.bytesRead, pixels * 8);
}

TEST_F(PostfxWorkAccountTest, DriverCountsAFullScreenPassAtLeastOncePerPixel) {
  // Without counting, fragments are the driver's (llvmpipe: 16 per 4x4 block a primitive
  // touches), samples passed exact.
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics | postfx::testing::BenchmarkFloor, false);
  dispatchResolved(*fx, fullPathFrame(scene, water()));
  const Summed floor = summed(*fx, "floor.inputs");
  ASSERT_EQ(floor.calls, 1);
  const std::uint64_t pixels = 96 * 54;
  EXPECT_EQ(floor.step.work.samplesPassed, pixels);
  EXPECT_GE(floor.step.work.fragments, pixels);
  EXPECT_LE(floor.step.work.fragments, 2 * pixels);
  EXPECT_EQ(floor.step.work.sources & postfx::kWorkCounted, 0u);
  EXPECT_NE(floor.step.work.sources & postfx::kWorkFromPipelineStatistics, 0u);
  // Fetches are then the shader's stated count per fragment times the driver's fragments.
  EXPECT_EQ(floor.step.work.fetches, floor.step.statedFetches);
}

// The seabed passes on their full path: the counted fetches are exactly the stated ones (the
// caustics on a near seabed, the god rays over a deep one).
TEST_F(PostfxWorkAccountTest, SeabedShadersDoWhatTheyStateOnTheirFullPath) {
  postfxtest::Scene near(fullPathSpec(false), GL_RGBA16F), deep(fullPathSpec(true), GL_RGBA16F);
  struct Case {
    const char* what;
    postfx::CausticsModel model;
    postfx::CausticsLookupResolution lookups;
    postfx::GodRayResolution godRays;
  };
  const Case cases[] = {
      {"ray deviation, full-resolution god rays", postfx::CausticsModel::RayDeviation,
       postfx::CausticsLookupResolution::Full, postfx::GodRayResolution::Full},
      {"tile irradiance, half-resolution lookups, quarter god rays",
       postfx::CausticsModel::TileIrradiance, postfx::CausticsLookupResolution::Half,
       postfx::GodRayResolution::Quarter},
      {"tile irradiance, full-resolution lookups, half god rays",
       postfx::CausticsModel::TileIrradiance, postfx::CausticsLookupResolution::Full,
       postfx::GodRayResolution::Half},
  };
  for (const Case& c : cases) {
    for (const postfxtest::Scene* scene : {&near, &deep}) {
      const bool god = scene == &deep;
      SCOPED_TRACE(std::string(c.what) + (god ? ", deep" : ", near"));
      auto fx = makeAccountingContext(
          Feature::Caustics | Feature::GodRays | postfx::testing::BenchmarkFloor, true);
      postfx::FrameDesc frame = fullPathFrame(*scene, water());
      frame.caustics.model = c.model;
      frame.caustics.tileLookupResolution = c.lookups;
      frame.godRays.resolution = c.godRays;
      dispatchResolved(*fx, frame);
      const std::vector<const char*> names =
          god ? std::vector<const char*>{"god_rays.march", "god_rays.upsample"}
              : std::vector<const char*>{"floor.inputs", "caustics.light", "caustics.tile_lookups"};
      for (const char* name : names) {
        const Summed s = summed(*fx, name);
        if (s.calls == 0) continue;
        SCOPED_TRACE(name);
        EXPECT_FALSE(s.step.statedBound);
        EXPECT_GT(s.step.work.fetches, 0u);
        EXPECT_EQ(s.step.work.atomics, s.step.statedAtomics);
        // The ray-deviation march skips the cascades too fine for a far sample's footprint:
        // there the statement is the near samples' path, a bound.
        if (god && c.model == postfx::CausticsModel::RayDeviation &&
            std::string(name) == "god_rays.march") {
          EXPECT_LE(s.step.work.fetches, s.step.statedFetches);
          EXPECT_GE(double(s.step.work.fetches), 0.5 * double(s.step.statedFetches));
        } else {
          EXPECT_EQ(s.step.work.fetches, s.step.statedFetches);
        }
      }
    }
  }
}

TEST_F(PostfxWorkAccountTest, GodRayFetchesGrowWithTheirSamples) {
  postfxtest::Scene scene(fullPathSpec(true), GL_RGBA16F);
  auto fetchesAt = [&](int samples) {
    auto fx = makeAccountingContext(Feature::Caustics | Feature::GodRays, true);
    postfx::FrameDesc frame = fullPathFrame(scene, water());
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    frame.godRays.sampleCount = samples;
    frame.godRays.resolution = postfx::GodRayResolution::Full;
    dispatchResolved(*fx, frame);
    const Summed march = summed(*fx, "god_rays.march");
    EXPECT_EQ(march.step.work.fragments, std::uint64_t(96 * 54));
    return double(march.step.work.fetches) / double(march.step.work.fragments);
  };
  const double at8 = fetchesAt(8), at16 = fetchesAt(16);
  // One depth fetch, then the same lookups at every sample: (1 + 16 k) / (1 + 8 k).
  const double perSample = (at8 - 1.0) / 8.0;
  EXPECT_GT(perSample, 1.0);
  EXPECT_NEAR(at16, 1.0 + 16.0 * perSample, 1e-9);
}

TEST_F(PostfxWorkAccountTest, TileFieldScalesWithItsResolution) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto scatterAt = [&](int resolution) {
    auto fx = makeAccountingContext(Feature::Caustics, true);
    postfx::FrameDesc frame = fullPathFrame(scene, water());
    frame.caustics.model = postfx::CausticsModel::TileIrradiance;
    frame.caustics.tileResolution = resolution;
    dispatchResolved(*fx, frame);
    return summed(*fx, "tile_irradiance.scatter");
  };
  const Summed at64 = scatterAt(64), at128 = scatterAt(128);
  ASSERT_GT(at64.calls, 0);
  // One dispatch per cascade with a field, of (points / 8)^2 groups of 8 x 8: four times the
  // points at twice the resolution.
  EXPECT_EQ(at128.calls, at64.calls);
  EXPECT_EQ(at128.step.work.computeInvocations, 4 * at64.step.work.computeInvocations);
  EXPECT_EQ(at128.step.work.dispatches, at64.step.work.dispatches);
  EXPECT_LE(at128.step.work.atomics, at128.step.statedAtomics);
}

TEST_F(PostfxWorkAccountTest, WindowGridCountsItsPointsAndTriangles) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics | Feature::WavefrontAreaRatio, true);
  postfx::FrameDesc frame = fullPathFrame(scene, water());
  frame.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  frame.caustics.gridResolution = 64;
  frame.caustics.depthLayers = 2;
  dispatchResolved(*fx, frame);
  const Summed vertices = summed(*fx, "wavefront_area_ratio.vertices");
  const Summed triangles = summed(*fx, "wavefront_area_ratio.triangles");
  const Summed points = summed(*fx, "wavefront_area_ratio.points");
  ASSERT_EQ(vertices.calls, 2);  // one per depth layer
  // The grid spans the window and a margin: gridResolution + 1 cells.
  const std::uint64_t cells = 65, side = cells + 1, groups = (side + 15) / 16;
  // 16 x 16 invocations per group, every group whole (the ones past the grid return at once).
  EXPECT_EQ(vertices.step.work.computeInvocations, 2 * groups * groups * 256);
  EXPECT_EQ(vertices.step.work.fetches, 2 * side * side * 3)
      << "each grid point reads every cascade once";
  EXPECT_EQ(vertices.step.work.fetches, vertices.step.statedFetches);
  // Two triangles per cell from the strips, one point per triangle.
  EXPECT_EQ(triangles.step.work.primitivesSubmitted, 2 * 2 * cells * cells);
  EXPECT_EQ(points.step.work.primitivesSubmitted, 2 * 2 * cells * cells);
  EXPECT_EQ(triangles.step.work.vertices, 2 * (2 * side) * cells);
  EXPECT_EQ(triangles.step.work.fetches, triangles.step.statedFetches);
  EXPECT_EQ(points.step.work.fetches, points.step.statedFetches);
}

TEST_F(PostfxWorkAccountTest, AFeatureOffCountsNothing) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics | Feature::GodRays, true);
  postfx::FrameDesc frame = fullPathFrame(scene, water());
  frame.godRays.enabled = false;
  dispatchResolved(*fx, frame);
  EXPECT_EQ(summed(*fx, "god_rays.march").calls, 0);
  EXPECT_EQ(summed(*fx, "god_rays.upsample").calls, 0);
  const postfx::WorkCounts& godRays = postfx::stats(*fx).pass(Pass::GodRays).work;
  EXPECT_EQ(godRays.draws + godRays.fragments + godRays.fetches + godRays.bytesRead, 0u);
  EXPECT_GT(postfx::stats(*fx).pass(Pass::Caustics).work.fragments, 0u);
}

TEST_F(PostfxWorkAccountTest, WithoutTheAccountNothingIsKept) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics | Feature::GodRays, true, false);
  dispatchResolved(*fx, fullPathFrame(scene, water()));
  EXPECT_EQ(postfx::workSteps(*fx).count, 0);
  EXPECT_EQ(postfx::stats(*fx).pass(Pass::Caustics).work.draws, 0u);
  EXPECT_GT(postfx::stats(*fx).pass(Pass::Caustics).samples, 0u);  // the timings still run
}

TEST_F(PostfxWorkAccountTest, PassSumsAreTheSumsOfTheirSteps) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics | Feature::GodRays, true);
  postfx::FrameDesc frame = fullPathFrame(scene, water());
  frame.caustics.model = postfx::CausticsModel::TileIrradiance;
  dispatchResolved(*fx, frame);
  for (Pass pass : {Pass::TileIrradiance, Pass::Caustics, Pass::GodRays}) {
    postfx::WorkCounts sum;
    const postfx::WorkSteps steps = postfx::workSteps(*fx);
    for (int i = 0; i < steps.count; ++i)
      if (steps.steps[i].pass == pass) sum += steps.steps[i].work;
    const postfx::WorkCounts& reported = postfx::stats(*fx).pass(pass).work;
    SCOPED_TRACE(postfx::toString(pass));
    EXPECT_GT(reported.draws + reported.dispatches, 0u);
    EXPECT_EQ(reported.fetches, sum.fetches);
    EXPECT_EQ(reported.fragments, sum.fragments);
    EXPECT_EQ(reported.computeInvocations, sum.computeInvocations);
    EXPECT_EQ(reported.bytesRead + reported.bytesWritten, sum.bytesRead + sum.bytesWritten);
  }
}

// A host that keeps a query of its own running (an occlusion query around the dispatch) keeps
// its target: the account leaves that counter out, and the host's query is undisturbed.
TEST_F(PostfxWorkAccountTest, AHostsActiveQueryKeepsItsTarget) {
  postfxtest::Scene scene(fullPathSpec(), GL_RGBA16F);
  auto fx = makeAccountingContext(Feature::Caustics, false);
  GLuint hostQuery = 0;
  glCreateQueries(GL_SAMPLES_PASSED, 1, &hostQuery);
  glBeginQuery(GL_SAMPLES_PASSED, hostQuery);
  dispatchResolved(*fx, fullPathFrame(scene, water()));
  GLint current = 0;
  glGetQueryiv(GL_SAMPLES_PASSED, GL_CURRENT_QUERY, &current);
  EXPECT_EQ(GLuint(current), hostQuery);
  glEndQuery(GL_SAMPLES_PASSED);
  GLuint64 hostSamples = 0;
  glGetQueryObjectui64v(hostQuery, GL_QUERY_RESULT, &hostSamples);
  EXPECT_GT(hostSamples, 0u);  // the plugin's draws were counted by the host's query
  glDeleteQueries(1, &hostQuery);
  const Summed light = summed(*fx, "caustics.light");
  ASSERT_EQ(light.calls, 1);
  EXPECT_EQ(light.step.work.sources & postfx::kWorkFromSamplesPassed, 0u);
  EXPECT_EQ(light.step.work.samplesPassed, 0u);
  EXPECT_GT(light.step.work.fragments, 0u);  // the statistics still ran
}

}  // namespace
