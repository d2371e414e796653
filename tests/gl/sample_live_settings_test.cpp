// The view's live settings (sample_app/src/live_settings.h): an edit the plugin refuses leaves
// its message and the frame the accepted settings give, bit for bit; an edit it accepts
// replaces them and clears the message. The overlay's widgets only fill LiveSettings::edited,
// so this is what a refused overlay value does.
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include <gl_fixture.h>

#include "live_settings.h"
#include "options.h"
#include "scene_setup.h"

namespace {

class LiveSettingsTest : public testsupport::GlTest {
 protected:
  void SetUp() override {
    testsupport::GlTest::SetUp();
    std::string known, error;
    ASSERT_TRUE(ocean::findPreset("seabed", preset_, known));
    ASSERT_TRUE(ocean::buildScene({}, scene_, error)) << error;
    ocean::RenderSettings settings;
    settings.width = 96;
    settings.height = 54;
    settings.waterResolution = 16;
    settings.shadowMapSize = 256;
    renderer_ = ocean::Renderer::create(settings, scene_, error);
    ASSERT_TRUE(renderer_) << error;
    plugin_ = ocean::PluginSetup::create(*renderer_, ocean::Options{}, false, error);
    ASSERT_TRUE(plugin_) << error;
    input_ = {preset_.camera, preset_.sun, 12.5};
    live_.accepted = ocean::currentSettings(*plugin_, *renderer_, preset_.sun);
    live_.edited = live_.accepted;
    ASSERT_TRUE(ocean::renderLive(live_, *plugin_, *renderer_, input_, error)) << error;
    accepted_ = renderer_->readColor();
  }

  // One frame with the edited settings handed over; the frame must render either way.
  void renderEdited() {
    live_.untried = true;
    std::string error;
    EXPECT_TRUE(ocean::renderLive(live_, *plugin_, *renderer_, input_, error)) << error;
    expectNoGlErrors("renderLive");
  }

  void expectRefused(const std::string& field) {
    renderEdited();
    EXPECT_NE(live_.refusal.find(field), std::string::npos)
        << "message should name " << field << ": " << live_.refusal;
    EXPECT_TRUE(renderer_->readColor() == accepted_) << "a refused edit changed the frame";
    EXPECT_FALSE(live_.untried) << "a refused edit is tried once, not every frame";
  }

  ocean::Preset preset_;
  ocean_scene::Model scene_;
  std::unique_ptr<ocean::Renderer> renderer_;
  std::unique_ptr<ocean::PluginSetup> plugin_;
  ocean::FrameInput input_;
  ocean::LiveSettings live_;
  std::vector<uint8_t> accepted_;
};

TEST_F(LiveSettingsTest, TileResolutionNotAPowerOfTwoIsRefused) {
  live_.edited.caustics.tileResolution = 100;
  expectRefused("tileResolution");
  EXPECT_EQ(live_.accepted.caustics.tileResolution, 128);
  EXPECT_EQ(live_.edited.caustics.tileResolution, 100) << "the user's value is kept to correct";
}

TEST_F(LiveSettingsTest, NaNGodRayIntensityIsRefused) {
  live_.edited.godRays.intensity = std::numeric_limits<float>::quiet_NaN();
  expectRefused("godRays.intensity");
}

// The view's context has the physical model's resources only when started with it.
TEST_F(LiveSettingsTest, ModelWithoutItsFeatureIsRefused) {
  live_.edited.caustics.model = postfx::CausticsModel::WavefrontAreaRatio;
  expectRefused("Feature::WavefrontAreaRatio");
}

TEST_F(LiveSettingsTest, AcceptedEditReplacesTheSettingsAndClearsTheMessage) {
  live_.edited.godRays.sampleCount = 1;
  expectRefused("sampleCount");
  live_.edited.godRays.sampleCount = 32;
  live_.edited.godRays.intensity = 1.5f;
  renderEdited();
  EXPECT_TRUE(live_.refusal.empty()) << live_.refusal;
  EXPECT_EQ(live_.accepted.godRays.sampleCount, 32);
  EXPECT_FALSE(renderer_->readColor() == accepted_) << "brighter god rays changed nothing";
}

}  // namespace
