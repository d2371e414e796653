// The harbour preset as the sample hands it to the plugin and draws it: Feature::
// ReflectedCaustics and the preset's reflected settings only where the run wants them, at the
// intensity that makes the plugin's sun (the beam below the surface) the sun the sea mirrors;
// --flat-water's texture flat in every cascade while the sample's own water is unchanged; and
// the sun's shadow map bent at the level (RenderSettings::airShadows), so the pier's shade on
// the quay's wall lies where the sun in air casts it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gl_fixture.h>
#include <scene/harbour_scene.h>

#include "camera.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "scene_setup.h"
#include "sun_light.h"
#include "view_flags.h"

namespace {

constexpr int kWidth = 160, kHeight = 90;

const ocean_scene::Model& harbourScene() {
  static const ocean_scene::Model model = [] {
    ocean_scene::Model built;
    std::string error;
    EXPECT_TRUE(ocean::buildScene({}, built, error, {}, ocean::SceneKind::Harbour)) << error;
    return built;
  }();
  return model;
}

ocean::Preset preset(const char* name) {
  ocean::Preset p;
  std::string known;
  EXPECT_TRUE(ocean::findPreset(name, p, known)) << name;
  return p;
}

ocean::RenderSettings settingsFor(const ocean::Preset& p, int width = kWidth,
                                  int height = kHeight) {
  ocean::RenderSettings settings;
  settings.width = width;
  settings.height = height;
  settings.waterResolution = 64;
  settings.windSpeed = p.windSpeed;
  settings.airShadows = p.airShadows;
  return settings;
}

class SampleHarbour : public testsupport::GlTest {};

TEST_F(SampleHarbour, PluginGetsReflectedCausticsOnlyWhereTheRunWantsThem) {
  const ocean::Preset harbour = preset("harbour");
  std::string error;
  auto renderer = ocean::Renderer::create(settingsFor(harbour), harbourScene(), error);
  ASSERT_TRUE(renderer) << error;
  {
    auto plugin = ocean::PluginSetup::create(
        *renderer, ocean::withPresetCaustics(ocean::Options{}, harbour), false, error);
    ASSERT_TRUE(plugin) << error;
    EXPECT_TRUE(
        postfx::hasFeature(plugin->createDesc().features, postfx::Feature::ReflectedCaustics));
    EXPECT_TRUE(postfx::hasFeature(plugin->createDesc().features, postfx::Feature::ShadowMask));
    ASSERT_TRUE(renderer->render({harbour.camera, harbour.sun, 1.0}, error)) << error;
    const postfx::ReflectedCausticsSettings& r = plugin->lastFrame().reflectedCaustics;
    EXPECT_TRUE(r.enabled);
    EXPECT_EQ(r.gridResolution, harbour.reflectedGrid);
    EXPECT_EQ(r.maxHeight, float(harbour.reflectedMaxHeight));
    EXPECT_TRUE(r.includeMirrorMean) << "the sample lights nothing with the sea's mirrored light";
    // Lambert's 1/pi of the sun above the water: the plugin's sun is the beam below it.
    const float transmission = ocean::sunTransmission(harbour.sun, renderer->optics().ior);
    ASSERT_GT(transmission, 0.5f);
    EXPECT_NEAR(r.intensity * transmission, 0.318309886f, 1e-6f);
    EXPECT_NEAR(glm::length(plugin->lastFrame().sun.irradiance),
                glm::length(ocean::sunIrradianceAboveWater(harbour.sun)) * transmission, 1e-5f);
    expectNoGlErrors("harbour");
  }
  ocean::Options off;
  off.reflectedCaustics = false;
  auto plugin =
      ocean::PluginSetup::create(*renderer, ocean::withPresetCaustics(off, harbour), false, error);
  ASSERT_TRUE(plugin) << error;
  EXPECT_FALSE(
      postfx::hasFeature(plugin->createDesc().features, postfx::Feature::ReflectedCaustics));
  ASSERT_TRUE(renderer->render({harbour.camera, harbour.sun, 1.0}, error)) << error;
  EXPECT_FALSE(plugin->lastFrame().reflectedCaustics.enabled);
  // The sun below the horizon: nothing to mirror, intensity 0 (in the plugin's range).
  ocean::Sun night = harbour.sun;
  night.elevation = glm::radians(-5.0);
  ASSERT_TRUE(renderer->render({harbour.camera, night, 1.0}, error)) << error;
  EXPECT_EQ(plugin->lastFrame().reflectedCaustics.intensity, 0.0f);
}

TEST_F(SampleHarbour, SeaPresetsLeaveReflectedCausticsOut) {
  const ocean::Preset seabed = preset("seabed");
  std::string error;
  ocean_scene::Model sea;
  ASSERT_TRUE(ocean::buildScene({}, sea, error)) << error;
  auto renderer = ocean::Renderer::create(settingsFor(seabed), sea, error);
  ASSERT_TRUE(renderer) << error;
  auto plugin = ocean::PluginSetup::create(
      *renderer, ocean::withPresetCaustics(ocean::Options{}, seabed), false, error);
  ASSERT_TRUE(plugin) << error;
  EXPECT_FALSE(
      postfx::hasFeature(plugin->createDesc().features, postfx::Feature::ReflectedCaustics));
  ASSERT_TRUE(renderer->render({seabed.camera, seabed.sun, 1.0}, error)) << error;
  EXPECT_FALSE(plugin->lastFrame().reflectedCaustics.enabled);
  EXPECT_EQ(plugin->lastFrame().water.texture.texture, renderer->ocean().slopeTexture());
}

// --flat-water: the plugin reads one zero texel per cascade (zero slopes and height; RG32F
// reads B = 0 and A = 1, flat water's Jacobian), statistics unknown, the tiles as the sea's.
TEST_F(SampleHarbour, FlatWaterHandsThePluginAFlatSeaAndLeavesTheSamplesWaterAlone) {
  const ocean::Preset harbour = preset("harbour");
  std::string error;
  auto renderer = ocean::Renderer::create(settingsFor(harbour), harbourScene(), error);
  ASSERT_TRUE(renderer) << error;
  const ocean::FrameInput input{harbour.camera, harbour.sun, 2.0};
  // Every plugin pass off: what is drawn is the sample's own.
  ocean::Options quiet = ocean::withPresetCaustics(ocean::Options{}, harbour);
  quiet.caustics = quiet.godRays = quiet.objectCaustics = false;
  quiet.reflectedCaustics = false;
  std::vector<float> waves, flatFrame;
  postfx::WaterSurface seaWater;
  {
    auto plugin = ocean::PluginSetup::create(*renderer, quiet, false, error);
    ASSERT_TRUE(plugin) << error;
    ASSERT_TRUE(renderer->render(input, error)) << error;
    waves = renderer->readRadiance();
    seaWater = plugin->lastFrame().water;
  }
  EXPECT_EQ(seaWater.texture.texture, renderer->ocean().slopeTexture());
  quiet.flatWater = true;
  auto plugin = ocean::PluginSetup::create(*renderer, quiet, false, error);
  ASSERT_TRUE(plugin) << error;
  ASSERT_TRUE(renderer->render(input, error)) << error;
  flatFrame = renderer->readRadiance();
  EXPECT_TRUE(waves == flatFrame) << "--flat-water changed the sample's own drawing";

  const postfx::WaterSurface& water = plugin->lastFrame().water;
  ASSERT_NE(water.texture.texture, 0u);
  EXPECT_NE(water.texture.texture, renderer->ocean().slopeTexture());
  EXPECT_EQ(water.texture.format, GLenum(GL_RG32F));
  EXPECT_EQ(water.cascadeCount, seaWater.cascadeCount);
  GLint target = 0, width = 0, height = 0, layers = 0;
  glGetTextureParameteriv(water.texture.texture, GL_TEXTURE_TARGET, &target);
  glGetTextureLevelParameteriv(water.texture.texture, 0, GL_TEXTURE_WIDTH, &width);
  glGetTextureLevelParameteriv(water.texture.texture, 0, GL_TEXTURE_HEIGHT, &height);
  glGetTextureLevelParameteriv(water.texture.texture, 0, GL_TEXTURE_DEPTH, &layers);
  EXPECT_EQ(target, GL_TEXTURE_2D_ARRAY);
  ASSERT_GE(layers, water.cascadeCount);
  std::vector<float> texels(size_t(width) * size_t(height) * size_t(layers) * 2, -1.0f);
  glGetTextureImage(water.texture.texture, 0, GL_RG, GL_FLOAT, GLsizei(texels.size() * 4),
                    texels.data());
  EXPECT_TRUE(std::all_of(texels.begin(), texels.end(), [](float v) { return v == 0.0f; }));
  for (int c = 0; c < water.cascadeCount; ++c) {
    EXPECT_EQ(water.tileSize[c], seaWater.tileSize[c]) << c;
    EXPECT_EQ(water.rmsLaplacian[c], 0.0) << c;
    EXPECT_EQ(water.longestWavelength[c], 0.0) << c;
  }
  expectNoGlErrors("flat water");
}

// A ray from `origin` along `dir` (pointing up) against an axis-aligned box: true if it meets it.
bool hits(const glm::dvec3& origin, const glm::dvec3& dir, glm::dvec3 lo, glm::dvec3 hi) {
  double near = 0.0, far = 1e9;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(dir[a]) < 1e-12) {
      if (origin[a] < lo[a] || origin[a] > hi[a]) return false;
      continue;
    }
    double t0 = (lo[a] - origin[a]) / dir[a], t1 = (hi[a] - origin[a]) / dir[a];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
  }
  return near <= far;
}

// The sample's lighting, no plugin: a stretch of the quay's wall left of the pier, seen square
// on from 7 m. Where the sun in air meets the pier's deck but the refracted sun (the map's own
// direction) passes above it, the bent map shades the wall and the unbent one lit it; where
// both pass clear of the pier, both light it alike.
TEST_F(SampleHarbour, AirShadowsPutThePiersShadeWhereTheSunInAirCastsIt) {
  const ocean::Preset harbour = preset("harbour");
  const ocean_scene::HarbourSceneParams params;
  const glm::dvec3 o(params.origin.x, 0.0, params.origin.y);
  ocean::Camera camera = harbour.camera;
  camera.position = o + glm::dvec3(-4.0, 1.0, 7.0);
  camera.yaw = 0.0;
  camera.pitch = glm::radians(-1.0);
  constexpr int kW = 320, kH = 180;
  std::vector<float> frames[2];
  for (int bent = 0; bent < 2; ++bent) {
    std::string error;
    ocean::RenderSettings settings = settingsFor(harbour, kW, kH);
    settings.airShadows = bent == 1;
    auto renderer = ocean::Renderer::create(settings, harbourScene(), error);
    ASSERT_TRUE(renderer) << error;
    ASSERT_TRUE(renderer->render({camera, harbour.sun, 1.0}, error)) << error;
    frames[bent] = renderer->readRadiance();
  }
  // The refracted sun, as the map is drawn along it.
  const glm::dvec3 toSun = harbour.sun.direction();
  const double ior = 1.333;
  const glm::dvec3 refracted = -glm::refract(-toSun, glm::dvec3(0, 1, 0), 1.0 / ior);
  const double margin = 0.15;  // m: clear of the PCF's blur and the normal offset
  const double underside = params.deckHeight - params.deckThickness;
  const glm::dvec3 deckLo = o + glm::dvec3(-0.5 * params.pierWidth, underside, 0.0);
  const glm::dvec3 deckHi =
      o + glm::dvec3(0.5 * params.pierWidth, params.deckHeight, params.pierLength);
  const glm::dvec3 pierLo = o + glm::dvec3(-0.5 * params.pierWidth, -20.0, 0.0);
  const glm::dvec3 shrink(margin), pad(margin);
  const glm::dmat4 viewProjection =
      camera.projection(double(kW) / kH) * glm::dmat4(camera.viewRotation());
  double shadedBent = 0.0, shadedFlat = 0.0, litBent = 0.0, litFlat = 0.0;
  int shaded = 0, lit = 0;
  for (double x = -6.5; x <= -1.9; x += 0.1) {
    for (double y = 0.35; y <= params.quayHeight - 0.2; y += 0.1) {
      const glm::dvec3 w = o + glm::dvec3(x, y, 0.0);
      const bool airHitsDeck = hits(w, toSun, deckLo + shrink, deckHi - shrink);
      const bool airClear = !hits(w, toSun, pierLo - pad, deckHi + pad);
      const bool refractedClear = !hits(w, refracted, pierLo - pad, deckHi + pad);
      if (!refractedClear || !(airHitsDeck || airClear)) continue;
      const glm::dvec4 clip =
          viewProjection * glm::dvec4(w + glm::dvec3(0, 0, 0.01) - camera.position, 1.0);
      const int px = int((clip.x / clip.w * 0.5 + 0.5) * kW);
      const int py = int((clip.y / clip.w * 0.5 + 0.5) * kH);  // GL rows, bottom first
      if (px < 1 || py < 1 || px >= kW - 1 || py >= kH - 1) continue;
      const size_t i = (size_t(py) * kW + size_t(px)) * 4 + 1;  // green
      const double bent = double(frames[1][i]), unbent = double(frames[0][i]);
      if (airHitsDeck) {
        shadedBent += bent;
        shadedFlat += unbent;
        ++shaded;
      } else {
        litBent += bent;
        litFlat += unbent;
        ++lit;
      }
    }
  }
  std::printf(
      "wall points in the pier's shade in air only: %d (bent %.4f, unbent %.4f); lit "
      "both ways: %d (bent %.4f, unbent %.4f)\n",
      shaded, shaded ? shadedBent / shaded : 0.0, shaded ? shadedFlat / shaded : 0.0, lit,
      lit ? litBent / lit : 0.0, lit ? litFlat / lit : 0.0);
  ASSERT_GE(shaded, 20);
  ASSERT_GE(lit, 20);
  EXPECT_LT(shadedBent, 0.5 * shadedFlat) << "the bent map misses the pier's shade in air";
  EXPECT_NEAR(litBent / litFlat, 1.0, 0.02) << "the bent map shades wall the sun reaches";
}

}  // namespace
