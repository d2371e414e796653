// Every preset of the sample renders at small size: no GL error, not blank, no NaN/Inf in the
// HDR radiance, and the same arguments give the same image bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include <gl_fixture.h>
#include <image_stats.h>

#include "camera.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "sample_default_scene.h"
#include "scene_setup.h"
#include "view_flags.h"

namespace {

class SampleRender : public testsupport::GlTest, public ::testing::WithParamInterface<const char*> {
 protected:
  struct Frame {
    std::vector<uint8_t> color;
    std::vector<float> radiance;
  };

  // lights: the preset's point and spot lights (the torch's), or none.
  Frame render(const char* presetName, double time, bool objectCaustics = true, bool lights = true,
               const ocean_scene::Model& scene = sampletest::defaultScene()) {
    ocean::Preset preset;
    std::string known, error;
    EXPECT_TRUE(ocean::findPreset(presetName, preset, known));
    ocean::RenderSettings settings;
    settings.width = 256;
    settings.height = 144;
    settings.waterResolution = 64;
    settings.shadowMapSize = 512;
    settings.windSpeed = preset.windSpeed;
    auto renderer = ocean::Renderer::create(settings, scene, error);
    EXPECT_TRUE(renderer) << error;
    if (!renderer) return {};
    if (lights) renderer->setLights(preset.lights);
    ocean::Options options;
    options.objectCaustics = objectCaustics;
    // The settings the preset is shown with, as the commands apply them.
    auto plugin = ocean::PluginSetup::create(*renderer, ocean::withPresetCaustics(options, preset),
                                             false, error);
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

// The object caustics (glass sphere, bottle, brass ring in the scene) only ever add light:
// every radiance value with them is >= without, and where their focus is in view, some is more.
TEST_P(SampleRender, ObjectCausticsOnlyAddLight) {
  const Frame on = render(GetParam(), 12.5, true);
  const Frame off = render(GetParam(), 12.5, false);
  ASSERT_EQ(on.radiance.size(), off.radiance.size());
  double added = 0.0, lowest = 0.0;
  size_t brighter = 0;
  for (size_t i = 0; i < on.radiance.size(); ++i) {
    const double d = double(on.radiance[i]) - double(off.radiance[i]);
    lowest = std::min(lowest, d);
    added += std::max(d, 0.0);
    brighter += d > 1e-4 ? 1 : 0;
  }
  std::printf(
      "%s: object caustics add %.4f (sum of radiance), %zu values brighter, lowest "
      "difference %.3g\n",
      GetParam(), added, brighter, lowest);
  EXPECT_GE(lowest, -1e-5);
  if (std::string(GetParam()) == "seabed" || std::string(GetParam()) == "shallow") {
    EXPECT_GT(brighter, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Presets, SampleRender,
                         ::testing::Values("seabed", "sunward", "above", "waterline", "torch",
                                           "shallow"));

class SampleTorch : public SampleRender {};

// The torch preset's spot light lights the sand itself (the renderer's own direct
// light, shadowed) and the plugin adds the glass sphere's caustic of it only inside the
// sphere's shadow: where the added light is bright, the torch's direct light is gone.
TEST_F(SampleTorch, CausticLiesInsideTheSphereShadow) {
  const Frame on = render("torch", 0.0, true);
  const Frame off = render("torch", 0.0, false);
  const Frame dark = render("torch", 0.0, false, false);
  ASSERT_EQ(on.radiance.size(), off.radiance.size());
  ASSERT_EQ(dark.radiance.size(), off.radiance.size());
  const size_t pixels = on.radiance.size() / 4;
  std::vector<double> caustic(pixels), direct(pixels);
  double causticPeak = 0.0, directPeak = 0.0, lowest = 0.0;
  for (size_t i = 0; i < pixels; ++i) {
    caustic[i] = double(on.radiance[4 * i + 1]) - double(off.radiance[4 * i + 1]);
    direct[i] = double(off.radiance[4 * i + 1]) - double(dark.radiance[4 * i + 1]);
    causticPeak = std::max(causticPeak, caustic[i]);
    directPeak = std::max(directPeak, direct[i]);
    lowest = std::min(lowest, caustic[i]);
  }
  // The sphere's focus, far brighter than the brass ring's reflection (which lands in the
  // torch's direct light, as a reflection does).
  double directThere = 0.0;
  size_t focus = 0;
  for (size_t i = 0; i < pixels; ++i) {
    if (caustic[i] < 0.25 * causticPeak) continue;
    directThere = std::max(directThere, direct[i]);
    ++focus;
  }
  std::printf(
      "torch: direct light peak %.4f, caustic peak %.4f over %zu pixels (>= 1/4 of it), "
      "where the direct light is at most %.4f\n",
      directPeak, causticPeak, focus, directThere);
  EXPECT_GT(directPeak, 0.0);
  EXPECT_GT(causticPeak, 0.5 * directPeak);  // a focus: brighter than the light it refills
  EXPECT_GT(focus, 4u);
  EXPECT_LT(directThere, 0.05 * directPeak);
  EXPECT_GE(lowest, -1e-5);
}

// The shallow reef's glass sphere and ring lie 60 m from the deep presets: outside their shadow
// maps, so the sample hands them to the plugin only on the reef. The seabed preset renders bit
// for bit the same without them (with them passed, the sun's caster map would span both sites).
TEST_F(SampleRender, FarReefCastersChangeNothingTheSeabedSees) {
  ocean_scene::Model withoutReef = sampletest::defaultScene();
  std::vector<ocean_scene::Instance> kept;
  for (const ocean_scene::Instance& instance : withoutReef.instances) {
    if (instance.name.rfind("shallow_", 0) != 0) kept.push_back(instance);
  }
  ASSERT_EQ(kept.size() + 2, withoutReef.instances.size()) << "the reef's sphere and ring";
  withoutReef.instances = kept;
  const Frame all = render("seabed", 12.5);
  const Frame deep = render("seabed", 12.5, true, true, withoutReef);
  ASSERT_FALSE(all.radiance.empty());
  EXPECT_TRUE(all.radiance == deep.radiance);
}

}  // namespace

// A preset's caustic settings (Preset::maxReceiverDepth, tileResolution, causticsLookup) reach
// the plugin where the command line left the default, and the command line's win; a preset
// without any keeps the plugin's defaults.
TEST_F(SampleRender, PresetCausticSettingsReachThePlugin) {
  std::string known, error;
  ocean::Preset shallow, seabed;
  ASSERT_TRUE(ocean::findPreset("shallow", shallow, known));
  ASSERT_TRUE(ocean::findPreset("seabed", seabed, known));
  ocean::RenderSettings settings;
  settings.width = 64;
  settings.height = 36;
  settings.waterResolution = 16;
  settings.shadowMapSize = 256;
  auto renderer = ocean::Renderer::create(settings, sampletest::defaultScene(), error);
  ASSERT_TRUE(renderer) << error;
  auto caustics = [&](const ocean::Options& options, const ocean::Preset& preset) {
    auto plugin = ocean::PluginSetup::create(*renderer, ocean::withPresetCaustics(options, preset),
                                             false, error);
    EXPECT_TRUE(plugin) << error;
    return plugin ? plugin->caustics() : postfx::CausticsSettings{};
  };
  const postfx::CausticsSettings defaults;
  const postfx::CausticsSettings hero = caustics({}, shallow);
  EXPECT_EQ(hero.maxReceiverDepth, 5.0f);
  EXPECT_EQ(hero.tileResolution, 512);
  EXPECT_EQ(hero.tileLookupResolution, postfx::CausticsLookupResolution::Full);
  ocean::Options chosen;
  chosen.maxReceiverDepth = 9.0;
  chosen.tileResolution = 128;
  chosen.causticsLookup = 2;
  const postfx::CausticsSettings overridden = caustics(chosen, shallow);
  EXPECT_EQ(overridden.maxReceiverDepth, 9.0f);
  EXPECT_EQ(overridden.tileResolution, 128);
  EXPECT_EQ(overridden.tileLookupResolution, postfx::CausticsLookupResolution::Half);
  const postfx::CausticsSettings deep = caustics({}, seabed);
  EXPECT_EQ(deep.maxReceiverDepth, defaults.maxReceiverDepth);
  EXPECT_EQ(deep.tileResolution, defaults.tileResolution);
  EXPECT_EQ(deep.tileLookupResolution, defaults.tileLookupResolution);
  EXPECT_EQ(deep.tileDepthLayers, defaults.tileDepthLayers);

  // `view` switching from the hero to seabed: its settings go back to the plugin's defaults,
  // except what the command line chose; the other fields stay as they were.
  postfx::CausticsSettings live = hero;
  live.tau = 123.0f;
  ocean::applyPresetCaustics({}, seabed, live);
  EXPECT_EQ(live.maxReceiverDepth, defaults.maxReceiverDepth);
  EXPECT_EQ(live.tileResolution, defaults.tileResolution);
  EXPECT_EQ(live.tileLookupResolution, defaults.tileLookupResolution);
  EXPECT_EQ(live.tau, 123.0f);
  ocean::Options fixedGrid;
  fixedGrid.tileResolution = 256;
  ocean::applyPresetCaustics(fixedGrid, shallow, live);
  EXPECT_EQ(live.tileResolution, 256);
  EXPECT_EQ(live.maxReceiverDepth, 5.0f);
}
