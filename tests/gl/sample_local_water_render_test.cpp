// The sample host's local water (local_water_source.h): the pool's water surface shows the
// simulation's ripples inside the pool and nothing changes outside it; the plugin is asked for
// Feature::LocalWater only with local water, and is handed the pool's region as the header
// says (Replace, a hard edge, the floor's depth, the simulation's own texture).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gl_fixture.h>
#include <image_stats.h>
#include <scene/pool_scene.h>

#include "camera.h"
#include "local_water_setup.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "ripple_simulation.h"
#include "sample_default_scene.h"

namespace {

constexpr int kWidth = 192, kHeight = 108;

ocean::RenderSettings smallSettings() {
  ocean::RenderSettings settings;
  settings.width = kWidth;
  settings.height = kHeight;
  settings.waterResolution = 64;
  settings.shadowMapSize = 512;
  return settings;
}

// The pool's water held still: a simulation the test drops into, not the scripted one.
class StillPool final : public ocean::LocalWaterSource {
 public:
  explicit StillPool(std::unique_ptr<ocean::RippleSimulation> sim) : sim_(std::move(sim)) {
    postfx::LocalWater region;
    region.size = sim_->desc().size;
    region.mode = postfx::LocalWaterMode::Replace;
    region.edgeBlend = 0.0f;
    region.maxDepth = 2.0f;
    regions_ = {region};
  }
  bool update(double, std::string&) override {
    regions_[0].texture = {sim_->texture(), GL_RGBA32F};
    return true;
  }
  const std::vector<postfx::LocalWater>& regions() const override { return regions_; }
  bool seaVisible() const override { return false; }
  const std::vector<ocean::InstanceMove>& moves() const override { return moves_; }
  bool addDrop(glm::dvec2) override { return false; }
  ocean::RippleSimulation& sim() { return *sim_; }

 private:
  std::unique_ptr<ocean::RippleSimulation> sim_;
  std::vector<postfx::LocalWater> regions_;
  std::vector<ocean::InstanceMove> moves_;
};

class SampleLocalWater : public testsupport::GlTest {};

// Caustics and god rays off: what changes is the sample's own surface, displaced and shaded by
// the region's height and slopes, over the pool's water only (the deck around it, the ball
// and everything above the water stay bit for bit).
TEST_F(SampleLocalWater, PoolSurfaceShowsTheRipplesOnlyInsideThePool) {
  std::string error, known;
  ocean::Preset preset;
  ASSERT_TRUE(ocean::findPreset("pool", preset, known));
  const ocean_scene::Model scene = ocean_scene::buildPoolScene();
  auto renderer = ocean::Renderer::create(smallSettings(), scene, error);
  ASSERT_TRUE(renderer) << error;
  ocean::RippleDesc desc;
  desc.resolution = 128;
  desc.size = {8.0, 8.0};
  auto sim = ocean::RippleSimulation::create(desc, error);
  ASSERT_TRUE(sim) << error;
  auto pool = std::make_shared<StillPool>(std::move(sim));
  renderer->setLocalWater(pool);
  ocean::Options options;
  options.caustics = false;
  options.godRays = false;
  auto plugin = ocean::PluginSetup::create(*renderer, options, false, error);
  ASSERT_TRUE(plugin) << error;
  const ocean::FrameInput input{preset.camera, preset.sun, 3.0};
  ASSERT_TRUE(renderer->render(input, error)) << error;
  const std::vector<float> flat = renderer->readRadiance();
  ASSERT_TRUE(pool->sim().addDrop({1.0, -0.5}, 1.5, 0.08));
  ASSERT_TRUE(pool->sim().addDrop({-2.0, 1.5}, 0.8, -0.06));
  pool->sim().step(250);  // 2.3 s: their rings spread over most of the pool
  ASSERT_TRUE(renderer->render(input, error)) << error;
  const std::vector<float> rippled = renderer->readRadiance();
  expectNoGlErrors("pool renders");
  ASSERT_EQ(flat.size(), rippled.size());
  EXPECT_EQ(testsupport::radianceStats(rippled).nonFinite, 0u);

  // Which pixels see the pool's water: the pool's rectangle at the level, projected.
  const double aspect = double(kWidth) / kHeight;
  auto insidePool = [&](int x, int y) {
    // The pixel's ray meets the level inside the pool's rectangle (the walls rise above it by
    // 0.3 m, so a pixel near the rim may see the rim instead: a 2-pixel margin is left out).
    const double tanHalf = std::tan(0.5 * preset.camera.fovY);
    const glm::dvec2 ndc(2.0 * (x + 0.5) / kWidth - 1.0, 2.0 * (y + 0.5) / kHeight - 1.0);
    const glm::dvec3 d =
        preset.camera.rotation() * glm::dvec3(ndc.x * tanHalf * aspect, ndc.y * tanHalf, -1.0);
    const double t = -preset.camera.position.y / d.y;
    const glm::dvec3 hit = preset.camera.position + t * d;
    return std::abs(hit.x) < 4.0 && std::abs(hit.z) < 4.0;
  };
  size_t changedInside = 0, changedOutside = 0, inside = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const size_t i = (size_t(y) * kWidth + size_t(x)) * 4;
      const bool changed =
          flat[i] != rippled[i] || flat[i + 1] != rippled[i + 1] || flat[i + 2] != rippled[i + 2];
      bool nearPool = false;  // within 2 pixels of a pool pixel
      for (int dy = -2; dy <= 2 && !nearPool; ++dy)
        for (int dx = -2; dx <= 2 && !nearPool; ++dx) nearPool = insidePool(x + dx, y + dy);
      if (insidePool(x, y)) {
        ++inside;
        changedInside += changed;
      } else if (!nearPool) {
        changedOutside += changed;
      }
    }
  }
  std::printf("%zu of %zu pool pixels changed, %zu outside it\n", changedInside, inside,
              changedOutside);
  ASSERT_GT(inside, size_t(kWidth * kHeight / 10));  // the pool fills a good part of the view
  // 94 % change (5696 of 6056 at 192x108); the rest lies where the rings have not reached.
  EXPECT_GT(changedInside, inside / 2) << "the ripples barely show on the pool's water";
  EXPECT_EQ(changedOutside, 0u) << "the deck changed with the pool's water";
}

// Feature::LocalWater only for a scene with local water; the pool's region handed as made.
TEST_F(SampleLocalWater, PluginGetsThePoolsRegionAndTheFeatureOnlyWithIt) {
  std::string error, known;
  ocean::Preset pool, seabed;
  ASSERT_TRUE(ocean::findPreset("pool", pool, known));
  ASSERT_TRUE(ocean::findPreset("seabed", seabed, known));
  {
    const ocean_scene::Model scene = ocean_scene::buildPoolScene();
    auto renderer = ocean::Renderer::create(smallSettings(), scene, error);
    ASSERT_TRUE(renderer) << error;
    ASSERT_TRUE(ocean::attachLocalWater(pool, scene, *renderer, error)) << error;
    auto plugin = ocean::PluginSetup::create(*renderer, ocean::Options{}, false, error);
    ASSERT_TRUE(plugin) << error;
    EXPECT_TRUE(postfx::hasFeature(plugin->createDesc().features, postfx::Feature::LocalWater));
    ASSERT_TRUE(renderer->render({pool.camera, pool.sun, 1.0}, error)) << error;
    const postfx::WaterSurface& water = plugin->lastFrame().water;
    ASSERT_EQ(water.localWaterCount, 1);
    const postfx::LocalWater& region = water.localWater[0];
    EXPECT_EQ(region.mode, postfx::LocalWaterMode::Replace);
    EXPECT_EQ(region.edgeBlend, 0.0f);
    EXPECT_EQ(region.maxDepth, 2.0f);
    EXPECT_EQ(region.gridResolution, 512);
    EXPECT_EQ(region.size, glm::dvec2(8.0));
    EXPECT_EQ(region.texture.format, GLenum(GL_RGBA32F));
    EXPECT_EQ(region.texture.texture, renderer->localWater()->regions()[0].texture.texture);
    EXPECT_NE(region.texture.texture, 0u);
    expectNoGlErrors("pool");
  }
  auto renderer = ocean::Renderer::create(smallSettings(), sampletest::defaultScene(), error);
  ASSERT_TRUE(renderer) << error;
  ASSERT_TRUE(ocean::attachLocalWater(seabed, sampletest::defaultScene(), *renderer, error));
  EXPECT_EQ(renderer->localWater(), nullptr);
  auto plugin = ocean::PluginSetup::create(*renderer, ocean::Options{}, false, error);
  ASSERT_TRUE(plugin) << error;
  EXPECT_FALSE(postfx::hasFeature(plugin->createDesc().features, postfx::Feature::LocalWater));
  ASSERT_TRUE(renderer->render({seabed.camera, seabed.sun, 1.0}, error)) << error;
  EXPECT_EQ(plugin->lastFrame().water.localWaterCount, 0);
  EXPECT_EQ(plugin->lastFrame().water.localWater, nullptr);
}

}  // namespace
