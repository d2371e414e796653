// The harbour preset (CPU): its sun lights the receivers it shows with the waves' reflected
// light, every reflecting point in view lies inside the plugin's window, its scene reaches the
// renderer and the traced reference, and the command line's new flags parse as documented
// (--reflected-caustics / --no-reflected-caustics over the preset's choice, refused together;
// --flat-water; --reflected-grid in the plugin's range, --reflected-landing depth|layers; the
// preset and the flags in the help).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <postfx/reflected_caustics.h>
#include <postfx/settings.h>
#include <scene/harbour_scene.h>

#include "camera.h"
#include "options.h"
#include "scene_setup.h"
#include "scene_triangles.h"
#include "view_flags.h"

namespace {

ocean::Preset harbour() {
  ocean::Preset preset;
  std::string known;
  EXPECT_TRUE(ocean::findPreset("harbour", preset, known)) << known;
  return preset;
}

// The direction from a receiver down to the flat water its reflected light comes from (the
// plugin's l_r), for the sun's `toSun`.
glm::dvec3 towardMirror(const glm::dvec3& toSun) {
  return {toSun.x, -toSun.y, toSun.z};
}

// Where that light left the level: the receiver moved along l_r down to y = 0.
glm::dvec3 mirrorPoint(const glm::dvec3& receiver, const glm::dvec3& toSun) {
  const glm::dvec3 l = towardMirror(toSun);
  return receiver + l * (receiver.y / -l.y);
}

// True when the camera sees direction `p - camera` inside a 16:9 frame.
bool inFrame(const ocean::Camera& camera, const glm::dvec3& p) {
  const glm::dvec3 v = glm::transpose(camera.rotation()) * (p - camera.position);
  if (v.z >= -camera.nearPlane) return false;
  const double t = std::tan(0.5 * camera.fovY);
  return std::abs(v.y / -v.z) <= t && std::abs(v.x / -v.z) <= t * 16.0 / 9.0;
}

TEST(SampleHarbour, PresetShowsTheHarbourWithReflectedCausticsInALowSun) {
  const ocean::Preset preset = harbour();
  EXPECT_EQ(preset.scene, ocean::SceneKind::Harbour);
  EXPECT_TRUE(preset.reflectedCaustics);
  EXPECT_TRUE(preset.airShadows);
  EXPECT_TRUE(postfx::kReflectedGridRange.contains(preset.reflectedGrid));
  EXPECT_TRUE(postfx::kReflectedHeightRange.contains(float(preset.reflectedMaxHeight)));
  // Above the quay's wall, its highest receiver.
  EXPECT_GE(preset.reflectedMaxHeight, ocean_scene::HarbourSceneParams{}.quayHeight);
  const double elevation = glm::degrees(preset.sun.elevation);
  EXPECT_GE(elevation, 20.0);
  EXPECT_LE(elevation, 30.0);
  EXPECT_GE(preset.windSpeed, 3.0);
  EXPECT_LE(preset.windSpeed, 5.0);
  // The other presets keep their own choice: no reflected caustics, no bent shadows.
  for (const char* name :
       {"shallow", "seabed", "sunward", "above", "waterline", "torch", "pool", "wake"}) {
    ocean::Preset other;
    std::string known;
    ASSERT_TRUE(ocean::findPreset(name, other, known)) << name;
    EXPECT_FALSE(other.reflectedCaustics) << name;
    EXPECT_FALSE(other.airShadows) << name;
    EXPECT_NE(other.scene, ocean::SceneKind::Harbour) << name;
  }
}

// The wall and the boat's side face the sun horizontally and take the mirrored light
// (n . l_r > 0); so does the pier's underside; the camera is below the underside and sees it.
TEST(SampleHarbour, ReceiversFaceTheMirroredSunAndTheCameraSeesTheUnderside) {
  const ocean::Preset preset = harbour();
  const ocean_scene::HarbourSceneParams params;
  const glm::dvec3 toSun = preset.sun.direction();
  const glm::dvec3 l = towardMirror(toSun);
  const glm::dvec3 wall(0.0, 0.0, 1.0), starboard(0.0, 0.0, 1.0), underside(0.0, -1.0, 0.0);
  for (const glm::dvec3& n : {wall, starboard}) {
    EXPECT_GT(n.x * toSun.x + n.z * toSun.z, 0.5 * glm::length(glm::dvec2(toSun.x, toSun.z)));
    EXPECT_GT(glm::dot(n, l), 0.5);
  }
  EXPECT_GT(glm::dot(underside, l), 0.3);
  const double undersideY = params.deckHeight - params.deckThickness;
  EXPECT_LT(preset.camera.position.y, undersideY - 0.3);
  EXPECT_GT(preset.camera.position.y, 0.3);  // above a calm sea's waves
  const glm::dvec3 middle(params.origin.x, undersideY, params.origin.y + 0.5 * params.pierLength);
  EXPECT_TRUE(inFrame(preset.camera, middle));
  // 8-20 m from the quay's face, looking at it.
  const double distance = preset.camera.position.z - params.origin.y;
  EXPECT_GE(distance, 8.0);
  EXPECT_LE(distance, 20.0);
  EXPECT_LT(preset.camera.forward().z, 0.0);
}

// Every point in view of the showcase (the pier's underside, the boat's side and the wall between
// them) reflects light from water inside the plugin's window around the camera, short of the
// outer eighth where the pattern fades to the flat mean.
TEST(SampleHarbour, ReflectingWaterOfEveryReceiverInViewLiesInsideTheWindow) {
  const ocean::Preset preset = harbour();
  const ocean_scene::HarbourSceneParams params;
  const glm::dvec3 toSun = preset.sun.direction();
  const double reach =
      0.5 * double(postfx::ReflectedCausticsSettings{}.windowSize) * (1.0 - 1.0 / 8.0);
  const glm::dvec3 o(params.origin.x, 0.0, params.origin.y);
  const double undersideY = params.deckHeight - params.deckThickness;
  std::vector<glm::dvec3> receivers;
  // The underside, the wall and the boat's side facing the harbour, sampled every 10 cm.
  for (double x = -0.5 * params.pierWidth; x <= 0.5 * params.pierWidth; x += 0.1)
    for (double z = 0.0; z <= params.pierLength; z += 0.1)
      receivers.push_back(o + glm::dvec3(x, undersideY, z));
  // The wall from the pier's far side to the boat's bow; farther along the quay it takes the
  // flat mean the plugin fades to beyond its window.
  for (double x = -0.5 * params.pierWidth - 1.0; x <= params.boatStern + params.boatLength;
       x += 0.1)
    for (double y = 0.05; y <= params.quayHeight; y += 0.1)
      receivers.push_back(o + glm::dvec3(x, y, 0.0));
  for (double x = 0.0; x <= params.boatLength; x += 0.1)
    for (double y = 0.05; y <= params.boatFreeboard; y += 0.1)
      receivers.push_back(o +
                          glm::dvec3(params.boatStern + x, y, params.boatGap + params.boatBeam));
  std::size_t seen = 0;
  double farthest = 0.0;
  for (const glm::dvec3& r : receivers) {
    if (!inFrame(preset.camera, r)) continue;
    ++seen;
    const glm::dvec3 w = mirrorPoint(r, toSun);
    farthest = std::max({farthest, std::abs(w.x - preset.camera.position.x),
                         std::abs(w.z - preset.camera.position.z)});
  }
  ASSERT_GT(seen, receivers.size() / 10);
  std::printf(
      "%zu receiver points in view, their water at most %.2f m from the camera along x "
      "or z (the window's unfaded half-side %.2f m)\n",
      seen, farthest, reach);
  EXPECT_LE(farthest, reach);
}

TEST(SampleHarbour, SceneHoldsTheSeaAndTheHarbourAndTheTraceSeesThem) {
  ocean_scene::Model sea, withHarbour;
  std::string error;
  ASSERT_TRUE(ocean::buildScene({}, sea, error)) << error;
  ASSERT_TRUE(ocean::buildScene({}, withHarbour, error, {}, ocean::SceneKind::Harbour)) << error;
  const ocean_scene::Model alone = ocean_scene::buildHarbourScene();
  ASSERT_EQ(withHarbour.instances.size(), sea.instances.size() + alone.instances.size());
  auto named = [](const ocean_scene::Model& model, const std::string& name) {
    return std::count_if(model.instances.begin(), model.instances.end(),
                         [&](const ocean_scene::Instance& i) { return i.name == name; });
  };
  for (const char* name : {ocean_scene::kHarbourQuayName, ocean_scene::kHarbourDeckName,
                           ocean_scene::kHarbourBeamsName, ocean_scene::kHarbourPilesName,
                           ocean_scene::kHarbourHullName, ocean_scene::kHarbourBottomName,
                           ocean_scene::kHarbourStrakeName, ocean_scene::kHarbourBoatDeckName,
                           ocean_scene::kHarbourCabinName}) {
    EXPECT_EQ(named(withHarbour, name), 1) << name;
    EXPECT_EQ(named(sea, name), 0) << name;
  }
  // The traced reference's triangles (sceneTriangles) hold the pier's underside: triangles
  // facing down at its height over the pier's area.
  const ocean_scene::HarbourSceneParams params;
  const double undersideY = params.deckHeight - params.deckThickness;
  double area = 0.0;
  for (const auto& mesh : ocean::sceneTriangles(withHarbour)) {
    for (const auto& t : mesh.triangles) {
      const glm::dvec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
      const glm::dvec3 cross = glm::cross(b - a, c - a);
      if (cross.y < 0.0 && std::abs(a.y - undersideY) < 1e-5 && std::abs(b.y - undersideY) < 1e-5 &&
          std::abs(c.y - undersideY) < 1e-5)
        area += 0.5 * glm::length(cross);
    }
  }
  EXPECT_NEAR(area, params.pierWidth * params.pierLength, 1e-3);
}

// The command line as main sees it.
ocean::ParsedCommandLine parse(const std::vector<std::string>& words) {
  std::vector<const char*> argv{"ocean_sample"};
  for (const std::string& w : words) argv.push_back(w.c_str());
  return ocean::parseCommandLine(int(argv.size()), argv.data());
}

TEST(SampleHarbour, ReflectedCausticsFlagsOverThePresetsChoice) {
  ocean::Preset shallow;
  std::string known;
  ASSERT_TRUE(ocean::findPreset("shallow", shallow, known));
  const ocean::Preset preset = harbour();

  const ocean::ParsedCommandLine plain = parse({"render", "--preset", "harbour"});
  ASSERT_EQ(plain.outcome, ocean::ParsedCommandLine::Outcome::Run) << plain.text;
  EXPECT_FALSE(plain.options.reflectedCaustics.has_value());
  EXPECT_FALSE(plain.options.flatWater);
  const ocean::Options harbourOptions = ocean::withPresetCaustics(plain.options, preset);
  EXPECT_EQ(harbourOptions.reflectedCaustics, std::optional<bool>(true));
  EXPECT_EQ(harbourOptions.reflectedGrid, preset.reflectedGrid);
  EXPECT_EQ(harbourOptions.reflectedMaxHeight, preset.reflectedMaxHeight);
  const ocean::Options shallowOptions = ocean::withPresetCaustics(plain.options, shallow);
  EXPECT_EQ(shallowOptions.reflectedCaustics, std::optional<bool>(false));
  EXPECT_EQ(shallowOptions.reflectedGrid, 0);  // the plugin's default

  const ocean::ParsedCommandLine off =
      parse({"render", "--preset", "harbour", "--no-reflected-caustics"});
  ASSERT_EQ(off.outcome, ocean::ParsedCommandLine::Outcome::Run) << off.text;
  EXPECT_EQ(ocean::withPresetCaustics(off.options, preset).reflectedCaustics,
            std::optional<bool>(false));
  const ocean::ParsedCommandLine on =
      parse({"view", "--reflected-caustics", "--reflected-grid", "256"});
  ASSERT_EQ(on.outcome, ocean::ParsedCommandLine::Outcome::Run) << on.text;
  const ocean::Options forced = ocean::withPresetCaustics(on.options, shallow);
  EXPECT_EQ(forced.reflectedCaustics, std::optional<bool>(true));
  EXPECT_EQ(forced.reflectedGrid, 256);
  EXPECT_EQ(ocean::withPresetCaustics(on.options, preset).reflectedGrid, 256);
}

TEST(SampleHarbour, ContradictingOrOutOfRangeFlagsAreRefused) {
  for (const auto& words :
       {std::vector<std::string>{"render", "--reflected-caustics", "--no-reflected-caustics"},
        std::vector<std::string>{"bench", "--no-reflected-caustics", "--preset", "harbour",
                                 "--reflected-caustics"}}) {
    const ocean::ParsedCommandLine parsed = parse(words);
    EXPECT_EQ(parsed.outcome, ocean::ParsedCommandLine::Outcome::Error);
    EXPECT_NE(parsed.text.find("--reflected-caustics"), std::string::npos) << parsed.text;
    EXPECT_NE(parsed.text.find("--no-reflected-caustics"), std::string::npos) << parsed.text;
    EXPECT_EQ(parsed.text.find('\n'), std::string::npos) << "one line: " << parsed.text;
  }
  for (const char* grid : {"32", "4096", "512.5", "many"}) {
    const ocean::ParsedCommandLine parsed = parse({"render", "--reflected-grid", grid});
    EXPECT_EQ(parsed.outcome, ocean::ParsedCommandLine::Outcome::Error) << grid;
    EXPECT_NE(parsed.text.find("--reflected-grid"), std::string::npos) << parsed.text;
  }
  for (const auto& [word, landing] : {std::pair{"depth", 1}, std::pair{"layers", 2}}) {
    const ocean::ParsedCommandLine parsed = parse({"render", "--reflected-landing", word});
    ASSERT_EQ(parsed.outcome, ocean::ParsedCommandLine::Outcome::Run) << parsed.text;
    EXPECT_EQ(parsed.options.reflectedLanding, landing) << word;
  }
  const ocean::ParsedCommandLine sideways = parse({"render", "--reflected-landing", "sideways"});
  EXPECT_EQ(sideways.outcome, ocean::ParsedCommandLine::Outcome::Error);
  EXPECT_NE(sideways.text.find("--reflected-landing"), std::string::npos) << sideways.text;
  // compare renders nothing: the scene's flags are not its own.
  const ocean::ParsedCommandLine compare = parse({"compare", "--flat-water"});
  EXPECT_EQ(compare.outcome, ocean::ParsedCommandLine::Outcome::Error);
  EXPECT_NE(compare.text.find("not one of compare's"), std::string::npos) << compare.text;
}

TEST(SampleHarbour, FlatWaterFlagAndHelp) {
  const ocean::ParsedCommandLine flat = parse({"reference", "--preset", "harbour", "--flat-water"});
  ASSERT_EQ(flat.outcome, ocean::ParsedCommandLine::Outcome::Run) << flat.text;
  EXPECT_TRUE(flat.options.flatWater);
  EXPECT_FALSE(flat.options.flatLocalWater);
  for (const char* command : {"render", "view", "bench", "reference"}) {
    const ocean::ParsedCommandLine help = parse({command, "--help"});
    ASSERT_EQ(help.outcome, ocean::ParsedCommandLine::Outcome::Help) << command;
    for (const char* word : {"harbour (", "--reflected-caustics", "--no-reflected-caustics",
                             "--flat-water", "--reflected-grid", "--reflected-landing"})
      EXPECT_NE(help.text.find(word), std::string::npos) << command << " --help lacks " << word;
  }
}

}  // namespace
