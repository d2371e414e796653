// A flicker test per pass. Each pass's added light, isolated as the report's
// temporal-stability rows isolate it (stability_sequence.h), follows the camera and time
// smoothly: nothing changes when nothing moves, and 16 times shorter steps change each frame
// far less (a smooth signal changes about 16 times less; noise drawn anew each frame, samples
// that slide with the camera or popping would not shrink). Where a reference is cheap enough
// for a test, the plugin changes no more than its reference over the same step, within a
// stated factor; the object caustics' temporal filter steadies them.
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

#include <gl_fixture.h>
#include <glm/gtc/matrix_transform.hpp>

#include "camera.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "sample_default_scene.h"
#include "scene_setup.h"
#include "stability_sequence.h"
#include "temporal_stability.h"

namespace {

using ocean::StabilityPass;

// The measure itself, on images with known answers.
TEST(AddedLightChange, KnownAnswers) {
  const std::vector<glm::vec4> dark(4, glm::vec4(0.0f)), grey(4, glm::vec4(1.0f));
  const std::vector<glm::vec4> brighter(4, glm::vec4(1.02f));
  std::vector<glm::vec4> half = dark;
  half[0] = half[1] = glm::vec4(2.0f);
  EXPECT_EQ(ocean::addedLightChange({grey, grey, grey}).mean, 0.0);
  // 2 % brighter: |1.02 - 1| over the pair's mean 1.01.
  EXPECT_NEAR(ocean::addedLightChange({grey, brighter}).mean, 0.02 / 1.01, 1e-6);
  // Light that moves to where there was none: all of it changes, twice its mean.
  std::vector<glm::vec4> moved = dark;
  moved[2] = moved[3] = glm::vec4(2.0f);
  EXPECT_NEAR(ocean::addedLightChange({half, moved}).mean, 2.0, 1e-9);
  // Pixels dark in both frames do not dilute the measure.
  EXPECT_NEAR(ocean::addedLightChange({half, half}).meanLight, 2.0, 1e-6);
  EXPECT_EQ(ocean::addedLightChange({dark, dark}).mean, 0.0);
  EXPECT_EQ(ocean::addedLightChange({grey}).pairs, 0);
}

// The seabed preset (sand, rock, the glass sphere and bottle in view) at a test's size.
class StabilityFixture : public testsupport::GlTest {
 protected:
  void makeHost(int width, int height, const ocean::Options& options = {}) {
    ocean::Preset preset;
    std::string known, error;
    ASSERT_TRUE(ocean::findPreset("seabed", preset, known));
    ocean::RenderSettings settings;
    settings.width = width;
    settings.height = height;
    settings.waterResolution = 64;
    settings.shadowMapSize = 512;
    renderer_ = ocean::Renderer::create(settings, sampletest::defaultScene(), error);
    ASSERT_TRUE(renderer_) << error;
    plugin_ = ocean::PluginSetup::create(*renderer_, options, false, error);
    ASSERT_TRUE(plugin_) << error;
    host_ = std::make_unique<ocean::StabilityHost>(ocean::StabilityHost{
        *renderer_, *plugin_, sampletest::defaultScene(), {preset.camera, preset.sun, 12.5}});
  }

  ocean::AddedLightChange passChange(StabilityPass pass, const ocean::StabilityMotion& motion,
                                     int frames = 3) {
    ocean::AddedLightFrames images;
    std::string error;
    EXPECT_TRUE(ocean::renderPassSequence(*host_, pass, motion, frames, images, error)) << error;
    expectNoGlErrors(ocean::stabilityPassName(pass));
    return ocean::addedLightChange(images);
  }

  ocean::AddedLightChange referenceChange(ocean::StabilityReference reference,
                                          const ocean::StabilityMotion& motion, int frames,
                                          const ocean::ReferenceSequenceSettings& settings) {
    ocean::AddedLightFrames images;
    std::string error;
    EXPECT_TRUE(
        ocean::renderReferenceSequence(*host_, reference, motion, frames, settings, images, error))
        << error;
    return ocean::addedLightChange(images);
  }

  std::unique_ptr<ocean::Renderer> renderer_;
  std::unique_ptr<ocean::PluginSetup> plugin_;
  std::unique_ptr<ocean::StabilityHost> host_;
};

class PassStability : public StabilityFixture,
                      public ::testing::WithParamInterface<StabilityPass> {};

// 128x72: big enough that each pass's light covers a few thousand pixels (the object
// caustics' focus a few hundred), small enough for 15 frames in a few seconds on llvmpipe.
TEST_P(PassStability, StillIsStillAndShorterStepsChangeLess) {
  makeHost(128, 72);
  if (HasFatalFailure()) return;
  const StabilityPass pass = GetParam();
  const ocean::AddedLightChange still = passChange(pass, ocean::stillMotion());
  // The pass must add light here, or the rest would pass on black frames.
  EXPECT_GT(still.meanLight, 0.0);
  // Same camera, same time, same inputs: the plugin is deterministic (and the temporal
  // filter's history of a still frame is that frame), so exactly nothing changes.
  EXPECT_EQ(still.mean, 0.0);
  for (const bool camera : {true, false}) {
    const ocean::AddedLightChange normal =
        passChange(pass, camera ? ocean::cameraMotion(30.0) : ocean::timeMotion(30.0), 2);
    const ocean::AddedLightChange shorter =
        passChange(pass, camera ? ocean::cameraMotion(480.0) : ocean::timeMotion(480.0), 2);
    std::printf("%s, %s: change %.5f at 30 fps, %.5f at 480 fps (p99 %.4f, %.4f)\n",
                ocean::stabilityPassName(pass), camera ? "camera moving" : "time running",
                normal.mean, shorter.mean, normal.p99, shorter.p99);
    RecordProperty(camera ? "camera_30fps" : "time_30fps", std::to_string(normal.mean));
    RecordProperty(camera ? "camera_480fps" : "time_480fps", std::to_string(shorter.mean));
    // The object caustics do not follow the waves (the casters refract the sun's unperturbed
    // refracted ray): with the camera still, running time changes exactly nothing.
    if (!camera &&
        (pass == StabilityPass::ObjectCaustics || pass == StabilityPass::FilteredObjectCaustics)) {
      EXPECT_EQ(normal.mean, 0.0);
      EXPECT_EQ(shorter.mean, 0.0);
      continue;
    }
    EXPECT_GT(normal.mean, 0.0) << (camera ? "camera" : "time");
    // A smooth signal: 16 times shorter steps, about 16 times less change (measured 13-19
    // times less for every pass except the physical model with time running: its fold cells,
    // finer than a pixel, change brightness faster than linearly over a 33 ms step; 4.9 times
    // with point lookups, 3.9 since its lookup filters the pixel's footprint, which took more
    // off the 33 ms change, 0.34 -> 0.20, than off the 2 ms one, 0.069 -> 0.051). 0.25 (1/3 for
    // that one) fails per-frame noise, sliding samples or popping, which do not shrink with the
    // step.
    const bool foldsInTime = !camera && pass == StabilityPass::WavefrontAreaRatio;
    EXPECT_LT(shorter.mean, (foldsInTime ? 1.0 / 3.0 : 0.25) * normal.mean)
        << (camera ? "camera" : "time");
  }
}

std::string passTestName(const ::testing::TestParamInfo<StabilityPass>& param) {
  static const char* const names[] = {
      "TileCaustics", "RayDeviationCaustics", "WavefrontAreaRatioCaustics",
      "GodRays",      "ObjectCaustics",       "FilteredObjectCaustics"};
  return names[int(param.param)];
}

INSTANTIATE_TEST_SUITE_P(EveryPass, PassStability,
                         ::testing::Values(StabilityPass::TileCaustics,
                                           StabilityPass::RayDeviationCaustics,
                                           StabilityPass::WavefrontAreaRatio,
                                           StabilityPass::GodRays, StabilityPass::ObjectCaustics,
                                           StabilityPass::FilteredObjectCaustics),
                         passTestName);

// Each pass is isolated from the host's own frame, whose settings are validated even for passes
// that do not run: a host on the physical model must not hand that model to the other passes'
// contexts, created without Feature::WavefrontAreaRatio (the report's stability section aborted).
TEST_F(StabilityFixture, EveryPassRunsWhateverTheHostsCausticsModel) {
  ocean::Options options;
  options.physicalCaustics = true;
  makeHost(64, 36, options);
  if (HasFatalFailure()) return;
  for (const StabilityPass pass :
       {StabilityPass::TileCaustics, StabilityPass::RayDeviationCaustics,
        StabilityPass::WavefrontAreaRatio, StabilityPass::GodRays, StabilityPass::ObjectCaustics,
        StabilityPass::FilteredObjectCaustics})
    EXPECT_GT(passChange(pass, ocean::stillMotion(), 2).meanLight, 0.0)
        << ocean::stabilityPassName(pass);
}

class ReferenceStability : public StabilityFixture {};

// The sample's receiver map is snapped to whole texels in the world, so a moving camera does
// not change the object caustic map: what changes on screen is the still caustic seen from
// elsewhere, which the truth does too and no filter in the map should remove. The filter must
// then change nothing (1 %: the map's float noise) and in particular add no lag.
TEST_F(ReferenceStability, TemporalFilterIsNeutralUnderCameraMotion) {
  makeHost(128, 72);
  if (HasFatalFailure()) return;
  const ocean::AddedLightChange plain =
      passChange(StabilityPass::ObjectCaustics, ocean::cameraMotion(), 3);
  const ocean::AddedLightChange filtered =
      passChange(StabilityPass::FilteredObjectCaustics, ocean::cameraMotion(), 3);
  std::printf("object caustics, camera moving: change %.5f unfiltered, %.5f filtered\n", plain.mean,
              filtered.mean);
  EXPECT_GT(plain.mean, 0.0);
  EXPECT_NEAR(filtered.mean, plain.mean, 0.01 * plain.mean);
}

// Where the map does flicker the filter steadies it: a host whose receiver depths jitter by
// 5 cm from frame to frame (as a shadow map refitted around the camera without snapping
// would), camera and time still. The filter (history weight 0.5, clamped to the new frame's
// 3x3 neighbourhood) must take out at least a quarter of the change; blending half the
// history in would halve it where the clamp lets it.
TEST_F(ReferenceStability, TemporalFilterSteadiesAJitteringReceiver) {
  makeHost(128, 72);
  if (HasFatalFailure()) return;
  const auto jitter = [](int frame, postfx::FrameDesc& desc) {
    // Every receiver seen 5 cm higher on odd frames: the map's decoded positions move by that.
    if (frame % 2)
      desc.objectCaustics.receivers.worldToLightClip =
          desc.objectCaustics.receivers.worldToLightClip *
          glm::translate(glm::dmat4(1.0), glm::dvec3(0.0, -0.05, 0.0));
  };
  std::string error;
  ocean::AddedLightFrames plainFrames, filteredFrames;
  ASSERT_TRUE(ocean::renderPassSequence(*host_, StabilityPass::ObjectCaustics, ocean::stillMotion(),
                                        5, plainFrames, error, jitter))
      << error;
  ASSERT_TRUE(ocean::renderPassSequence(*host_, StabilityPass::FilteredObjectCaustics,
                                        ocean::stillMotion(), 5, filteredFrames, error, jitter))
      << error;
  const ocean::AddedLightChange plain = ocean::addedLightChange(plainFrames);
  const ocean::AddedLightChange filtered = ocean::addedLightChange(filteredFrames);
  std::printf("object caustics, jittering receiver: change %.5f unfiltered, %.5f filtered\n",
              plain.mean, filtered.mean);
  EXPECT_GT(plain.mean, 0.0);
  EXPECT_LT(filtered.mean, 0.75 * plain.mean);
}

// The dense march (1024 segments per pixel, double) against the plugin's 16-sample march over
// the same two frames, 64x36 (the march costs about a second a frame there).
TEST_F(ReferenceStability, GodRaysChangeLikeTheirDenseMarch) {
  makeHost(64, 36);
  if (HasFatalFailure()) return;
  const ocean::ReferenceSequenceSettings settings;
  for (const bool camera : {true, false}) {
    const ocean::StabilityMotion motion = camera ? ocean::cameraMotion() : ocean::timeMotion();
    const ocean::AddedLightChange plugin = passChange(StabilityPass::GodRays, motion, 2);
    const ocean::AddedLightChange truth =
        referenceChange(ocean::StabilityReference::DenseGodRays, motion, 2, settings);
    std::printf("god rays, %s: plugin %.5f, dense march %.5f\n",
                camera ? "camera moving" : "time running", plugin.mean, truth.mean);
    EXPECT_GT(truth.mean, 0.0);
    // Measured 2.3 (camera) and 1.8 (time) times the march's change here, 3.1 and 3.3 at the
    // report's 160x90: 16 samples per ray each see the caustic pattern in the water at one
    // point, where the integral averages many filaments, so they change more as the pattern
    // moves; that excess is what docs/temporal_stability.md reports. 3 keeps it from growing
    // unnoticed at this size; samples that slid with the camera would change several times
    // more (PostfxGodRaysTest.WorldSnappedSamplingFlickersLessThanUniform).
    EXPECT_LT(plugin.mean, 3.0 * truth.mean);
  }
}

// The traced caustics (photons through the frame's own water, 4 batches, the same photons
// every frame) against every caustics model over the same two frames, 64x36.
TEST_F(ReferenceStability, CausticsChangeLikeTracedLight) {
  makeHost(64, 36);
  if (HasFatalFailure()) return;
  ocean::ReferenceSequenceSettings settings;
  settings.traceBatches = 4;
  for (const bool camera : {true, false}) {
    const ocean::StabilityMotion motion = camera ? ocean::cameraMotion() : ocean::timeMotion();
    const ocean::AddedLightChange truth =
        referenceChange(ocean::StabilityReference::TracedCaustics, motion, 2, settings);
    EXPECT_GT(truth.mean, 0.0);
    // Tile irradiance and ray deviation: measured 0.4-0.8 times the traced change (the
    // trace's own noise adds to its change; the models are smoother than traced light), so
    // 1.5 fails only a model that changes clearly more than the light it stands for.
    // Physical (wavefront area ratio): measured 2.1 (camera) and 4.9 (time) times the traced
    // change, flicker beyond the truth's that docs/temporal_stability.md reports; 3 and 6 keep
    // it from growing unnoticed.
    const struct {
      StabilityPass pass;
      double factor;
    } models[] = {{StabilityPass::TileCaustics, 1.5},
                  {StabilityPass::RayDeviationCaustics, 1.5},
                  {StabilityPass::WavefrontAreaRatio, camera ? 3.0 : 6.0}};
    for (const auto& model : models) {
      const ocean::AddedLightChange plugin = passChange(model.pass, motion, 2);
      std::printf("%s, %s: plugin %.5f, traced %.5f\n", ocean::stabilityPassName(model.pass),
                  camera ? "camera moving" : "time running", plugin.mean, truth.mean);
      EXPECT_LT(plugin.mean, model.factor * truth.mean) << ocean::stabilityPassName(model.pass);
    }
  }
}

}  // namespace
