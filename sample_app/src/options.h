#pragma once
// Command-line options of ocean_sample. Parsing validates everything it can before any GL
// work starts, so bad input fails fast with one line and leaves no output behind.
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <scene/gltf_limits.h>

#include "model_spec.h"
#include "scene_light.h"

namespace ocean {

enum class Command { Help, Render, View, Bench, Report, Reference, Compare };

struct Options {
  Command command = Command::Help;
  std::string preset = "shallow";  // the hero view (camera.cpp); README leads with it
  int width = 1280, height = 720;
  bool heightGiven = false;  // --height was on the command line (--cube-map refuses it)
  double timeSeconds = 0.0;
  // Extra glTF files placed in the scene: each --model (FILE[@x,y,z][:fit=M|none]), then each
  // --model-file (a path taken literally, placed in the row at the default size).
  std::vector<ModelSpec> models;
  // --model-limits: the work budget each file is held to before it is expanded.
  ocean_scene::GltfLimits modelLimits;
  std::vector<SceneLight> lights;  // --light: added to the preset's lights
  std::string out = "ocean.png";
  // bench: measured frames after warm-up; render: frames of the image sequence (1: one image);
  // view: frames drawn before it quits (0: until the window is closed)
  int frames = 60;
  double fps = 30.0;        // render, view --frames: frames per second of the sequence's time
  bool freezeTime = false;  // render/view --frames: time stays at --time
  // render: the image split into this many side-by-side views of one world (the preset's camera
  // on the left, each next one 4 m to its right and turned 0.5 rad back toward it), handed to
  // the plugin in one dispatch; 1: one view.
  int views = 1;
  // render: a cube-map probe at the camera instead: six faces of --width / 4, one dispatch,
  // written as a horizontal cross (4 x 3 faces).
  bool cubeMap = false;
  // render: a side-by-side stereo pair instead: two parallel eyes 6.4 cm apart about the camera,
  // each half the width, one dispatch (left eye on the left).
  bool stereo = false;
  std::string screenshot;  // view: the window's last frame as PNG ("": none)
  bool overlay = true;     // view: the Dear ImGui overlay (timings, live settings)
  std::string json;        // bench: JSON output path
  std::string only;        // bench: run only the variant rows whose name starts with this
  // bench --work: each pass's work account and its estimated GPU time on the GPU classes named
  // by --gpu (comma-separated, docs/gpu_cost.md) instead of the timing variants.
  bool work = false;
  std::string gpu = "rtx3060";
  // How the plugin's context keeps its work account (PluginSetup): off, the driver's queries,
  // or counted in the shaders as well (testing::CountShaderWork).
  // Timed: the driver's queries with each step timed alone (testing::TimeEachStep).
  enum class WorkAccount { Off, Queries, Counted, Timed } workAccount = WorkAccount::Off;
  bool caustics = true;        // the plugin's seabed caustics
  bool godRays = true;         // the plugin's underwater god rays
  bool objectCaustics = true;  // the plugin's light-map caustics of glass and metal models
  // The light those objects focus, seen in the water (Feature::VolumeCaustics): with
  // --volume-caustics only, since with the object caustics it exceeds their GPU budget
  // (docs/gpu_cost.md); --volume-method: 1 beams, 2 lines, 0 the plugin's default (beams).
  bool volumeCaustics = false;
  int volumeMethod = 0;
  // The plugin is given the local water regions (pool, wake) with flat surfaces, the sample's
  // own drawing unchanged: with --caustics-model ray-deviation --tau 0, flat water's frame of
  // a scene with local water (compare --flat).
  bool flatLocalWater = false;
  // The local water regions' grid cells per side (LocalWater::gridResolution); 0 keeps the
  // scene's. The report's error-against-time rows of the pool sweep it.
  int localWaterGrid = 0;
  // The plugin's reflected caustics above the water: --reflected-caustics or
  // --no-reflected-caustics, over the preset's choice (unset: Preset::reflectedCaustics, which
  // withPresetCaustics fills in).
  std::optional<bool> reflectedCaustics;
  // --reflected-grid: their water grid cells per side (ReflectedCausticsSettings::
  // gridResolution); 0 keeps the preset's (Preset::reflectedGrid), else the plugin's default.
  int reflectedGrid = 0;
  // Their highest layer's height (ReflectedCausticsSettings::maxHeight, m); 0 keeps the plugin's
  // default. No flag: the preset's (Preset::reflectedMaxHeight).
  double reflectedMaxHeight = 0.0;
  // --reflected-landing: where their mirrored rays are followed to (ReflectedCausticsSettings::
  // landing): 1 the view's depth, 2 height layers; 0 keeps the plugin's default.
  int reflectedLanding = 0;
  // The plugin is given a flat sea (zero slopes and heights in every cascade) instead of the
  // ocean's texture, the sample's own drawing unchanged: flat water's frame of the reflected
  // caustics for compare --flat (the seabed's has --caustics-model ray-deviation --tau 0).
  bool flatWater = false;
  double tau = -1.0;  // caustics tightening; < 0 keeps the plugin's default
  // Caustics model: the tile irradiance (the plugin's default) unless one of these is set:
  // the wavefront area-ratio irradiance window (Feature::WavefrontAreaRatio, with this
  // grid resolution) or the ray deviation.
  bool physicalCaustics = false;
  bool rayDeviationCaustics = false;  // the ray-deviation model instead of the tile irradiance
  int causticsGrid = 256;
  double causticsWindow = 32.0;  // its window's side (CausticsSettings::windowSize, m)
  int causticsLayers = 4;        // its receiver depth layers (CausticsSettings::depthLayers)
  // World-axis tri-planar lookup on steep surfaces (Feature::TriplanarWalls).
  bool triplanarWalls = false;
  // Tile-irradiance lookup resolution divisor: 1 full, 2 half; 0 keeps the plugin's default.
  int causticsLookup = 0;
  // Tile-irradiance texels per cascade tile side (CausticsSettings::tileResolution); 0 keeps
  // the plugin's default.
  int tileResolution = 0;
  // Deepest receiver layer of the caustic irradiance (CausticsSettings::maxReceiverDepth, m);
  // 0 keeps the preset's (the plugin's default unless the preset says otherwise).
  double maxReceiverDepth = 0.0;
  // Tile-irradiance depth layers per cascade, 4 or 8 (CausticsSettings::tileDepthLayers); 0 keeps
  // the plugin's default.
  int tileDepthLayers = 0;
  // God-ray march resolution divisor: 1 full, 2 half, 4 quarter; 0 keeps the plugin's default.
  int godRayResolution = 0;
  int godRaySamples = 0;  // GodRaySettings::sampleCount; 0 keeps the plugin's default
  int waterResolution = 256;
  bool quick = false;  // report: a smoke run in a few minutes
  // Camera and sun over the preset's (each unset keeps the preset's value); see view_flags.h.
  std::optional<glm::dvec3> cameraPosition, cameraLookAt;  // metres, y up, water at y = 0
  std::optional<double> fovDegrees;                        // vertical field of view
  std::optional<double> sunAzimuthDegrees, sunElevationDegrees;
  std::optional<double> exposureStops;  // EV before the tone curve (Preset::exposureStops)
  // render --frames: the camera's slow path, metres per second (with a look-at it keeps turning
  // to the target)
  std::optional<glm::dvec3> cameraVelocity;
  // reference: the traced frame (see frame_caustics_reference.h for each value's meaning)
  unsigned long long seed = 1;
  double noise = 0.05;            // target of the lit pixels' 99th-percentile noise
  double kernelScale = 1.0;       // kernel radius in pixel footprints
  double minKernelRadius = 0.01;  // m
  int maxBatches = 24;
  int threads = 2;
  // compare: the three frames (EXR) it reads
  std::string pluginImage, referenceImage, baseImage, flatImage;
};

inline constexpr int kMaxImageSide = 16384;

// What main does with the command line: run options.command, print `text` (the help asked
// for) and exit 0, or print `text` (one line) and exit 2.
struct ParsedCommandLine {
  enum class Outcome { Run, Help, Error } outcome = Outcome::Error;
  Options options;
  std::string text;
};

ParsedCommandLine parseCommandLine(int argc, const char* const* argv);

}  // namespace ocean
