// Every preset of the sample renders at small size: no GL error, not blank, no NaN/Inf in the
// HDR radiance, and the same arguments give the same image bit for bit.
#include <gtest/gtest.h>

#include <gl_fixture.h>
#include <image_stats.h>

#include "camera.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "scene_setup.h"

namespace {

class SampleRender : public testsupport::GlTest, public ::testing::WithParamInterface<const char*> {
 protected:
  static const ocean_scene::Model& scene() {
    static const ocean_scene::Model model = [] {
      ocean_scene::Model built;
      std::string error;
      EXPECT_TRUE(ocean::buildScene({}, built, error)) << error;
      return built;
    }();
    return model;
  }

  struct Frame {
    std::vector<uint8_t> color;
    std::vector<float> radiance;
  };

  Frame render(const char* presetName, double time) {
    ocean::Preset preset;
    std::string known, error;
    EXPECT_TRUE(ocean::findPreset(presetName, preset, known));
    ocean::RenderSettings settings;
    settings.width = 256;
    settings.height = 144;
    settings.waterResolution = 64;
    settings.shadowMapSize = 512;
    auto renderer = ocean::Renderer::create(settings, scene(), error);
    EXPECT_TRUE(renderer) << error;
    if (!renderer) return {};
    ocean::Options options;
    auto plugin = ocean::PluginSetup::create(*renderer, options, false, error);
    EXPECT_TRUE(plugin) << error;
    EXPECT_TRUE(renderer->render({preset.camera, preset.sun, time}, error)) << error;
    expectNoGlErrors(presetName);
    return {renderer->readColor(), renderer->readRadiance()};
  }
};

TEST_P(SampleRender, RendersFiniteNonBlankDeterministicImage) {
  const Frame first = render(GetParam(), 12.5);
  const testsupport::RadianceStats stats = testsupport::radianceStats(first.radiance);
  EXPECT_EQ(stats.nonFinite, 0u) << "NaN or Inf radiance values";
  EXPECT_GT(stats.mean, 1e-3) << "image is black";
  // A blank or single-colour frame has no spread; the scene has sky, sand, rock and water.
  EXPECT_GT(testsupport::byteImageSpread(first.color), 4.0);
  const Frame second = render(GetParam(), 12.5);
  EXPECT_TRUE(first.color == second.color) << "same arguments, different image";
  EXPECT_TRUE(first.radiance == second.radiance);
}

INSTANTIATE_TEST_SUITE_P(Presets, SampleRender,
                         ::testing::Values("seabed", "sunward", "above", "waterline"));

}  // namespace
