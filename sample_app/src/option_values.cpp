#include "option_values.h"

#include <postfx/postfx.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "caustics_model_names.h"
#include "light_spec.h"
#include "model_limits_option.h"

namespace ocean {
namespace {

bool parseInt(std::string_view text, int& value) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

// A number strtod reads whole and without leaving double's range: 1e-400 (which it rounds to 0)
// and 1e400 are refused rather than silently changed. NaN and infinities are left to the
// callers' range checks, which every one of them has.
bool parseDouble(std::string_view text, double& value) {
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(copy.c_str(), &end);
  return !copy.empty() && end == copy.c_str() + copy.size() && errno != ERANGE;
}

std::string got(std::string_view text) {
  return ", got '" + std::string(text) + "'";
}

bool intIn(std::string_view text, int lo, int hi, int& value, std::string_view flag,
           std::string& error) {
  int parsed = 0;
  if (!parseInt(text, parsed) || parsed < lo || parsed > hi) {
    error = std::string(flag) + " must be an integer in [" + std::to_string(lo) + ", " +
            std::to_string(hi) + "]" + got(text);
    return false;
  }
  value = parsed;
  return true;
}

// `what` describes the range in the refusal ("a number in [0, 1e6]").
bool doubleIn(std::string_view text, double lo, double hi, double& value, std::string_view flag,
              std::string_view what, std::string& error) {
  double parsed = 0.0;
  if (!parseDouble(text, parsed) || !(parsed >= lo && parsed <= hi)) {
    error = std::string(flag) + " must be " + std::string(what) + got(text);
    return false;
  }
  value = parsed;
  return true;
}

// The same for a value that overrides a preset's only when given.
bool doubleIn(std::string_view text, double lo, double hi, std::optional<double>& value,
              std::string_view flag, std::string_view what, std::string& error) {
  double parsed = 0.0;
  if (!doubleIn(text, lo, hi, parsed, flag, what, error)) return false;
  value = parsed;
  return true;
}

// Far from the origin is a case the plugin handles (double positions); beyond 1e7 m a float
// camera-relative offset has lost centimetres, which no scene of the sample needs.
constexpr double kMaxCoordinate = 1e7;

// x,y,z; `unit` names them in the refusal ("metres").
bool point(std::string_view text, std::optional<glm::dvec3>& value, std::string_view flag,
           std::string_view unit, std::string& error) {
  glm::dvec3 p{};
  size_t start = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const size_t comma = axis < 2 ? text.find(',', start) : text.size();
    double c = 0.0;
    if (comma == std::string_view::npos || !parseDouble(text.substr(start, comma - start), c) ||
        !(std::abs(c) <= kMaxCoordinate)) {
      error = std::string(flag) + " must be x,y,z in " + std::string(unit) + ", each within +-1e7" +
              got(text);
      return false;
    }
    p[axis] = c;
    start = comma + 1;
  }
  value = p;
  return true;
}

std::string causticsModelList() {
  std::string list;
  for (const CausticsModelName& model : kCausticsModelNames) {
    if (!model.listed) continue;
    list += (list.empty() ? "" : " or ") + std::string(model.name);
  }
  return list;
}

const std::array kValueOptions{
    ValueOption{"--preset", "NAME",
                "shallow, seabed, sunward, above, waterline, torch, pool, wake or harbour "
                "(default shallow)",
                false,
                [](std::string_view text, Options& o, std::string&) {
                  o.preset = text;  // checked against the presets when the scene is built
                  return true;
                }},
    ValueOption{"--width", "W", "image width in pixels (default 1280)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 1, kMaxImageSide, o.width, "--width", error);
                }},
    ValueOption{"--height", "H", "image height in pixels (default 720)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  o.heightGiven = true;
                  return intIn(text, 1, kMaxImageSide, o.height, "--height", error);
                }},
    ValueOption{"--time", "T", "animation time in seconds (default 0)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, -1e12, 1e12, o.timeSeconds, "--time",
                                  "a finite number of seconds within +-1e12", error);
                }},
    ValueOption{"--model", "FILE[@x,y,z][:fit=M|none]",
                "a glTF (.glb/.gltf) added as glass or metal casters (repeatable)", true,
                [](std::string_view text, Options& o, std::string& error) {
                  ModelSpec spec;  // the file and its placement: model_spec.cpp
                  if (!parseModelSpec(std::string(text), spec, error)) return false;
                  o.models.push_back(spec);
                  return true;
                }},
    ValueOption{"--model-file", "PATH",
                "a glTF added like --model, its path taken literally (for names with '@' or "
                "':fit='), in the row at the default size (repeatable; after the --model files)",
                true,
                [](std::string_view text, Options& o, std::string& error) {
                  if (text.empty()) {
                    error = "--model-file: no file name";
                    return false;
                  }
                  ModelSpec spec;
                  spec.path = text;
                  o.models.push_back(spec);
                  return true;
                }},
    ValueOption{"--model-limits", "KEY=N[,KEY=N]...",
                "the work budget of each glTF: triangles (after instancing, default 4194304), "
                "instances (16384), nodes (65536), bytes (once expanded, default 1G), "
                "json-values (values in the JSON, 1048576), pixels (texture pixels decoded, "
                "33554432); N in [1, 2^40], a k/M/G suffix allowed",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return parseModelLimits(text, o.modelLimits, error);
                }},
    ValueOption{"--light", "TYPE:...",
                "a point or spot light (repeatable, at most 4 with the preset's): "
                "point:X,Y,Z:I[:RANGE] or spot:X,Y,Z:DX,DY,DZ:I:CONE[:SOFTNESS[:RANGE]]",
                true,
                [](std::string_view text, Options& o, std::string& error) {
                  if (int(o.lights.size()) == kMaxSceneLights) {
                    error = "--light: at most " + std::to_string(kMaxSceneLights) + " lights";
                    return false;
                  }
                  SceneLight light;
                  if (!parseLightSpec(text, light, error)) return false;
                  o.lights.push_back(light);
                  return true;
                }},
    ValueOption{"--water-resolution", "N", "FFT texels per cascade side, 16..512 (default 256)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  // 16 at least: the scene's cascades (250, 37 and 5.3 m tiles) hand over
                  // between bands only where the finer tile is more than 2/N of the coarser one
                  // (the water module's rule).
                  int n = 0;
                  if (!parseInt(text, n) || n < 16 || n > 512 || (n & (n - 1)) != 0) {
                    error = "--water-resolution must be a power of two in [16, 512]" + got(text);
                    return false;
                  }
                  o.waterResolution = n;
                  return true;
                }},
    ValueOption{"--tau", "T", "seabed caustics tightening, 0..1e6 (default: the plugin's)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, 0.0, 1e6, o.tau, "--tau", "a number in [0, 1e6]", error);
                }},
    ValueOption{"--caustics-model", "MODEL",
                "tile (default), ray-deviation or wavefront-area-ratio", false,
                [](std::string_view text, Options& o, std::string& error) {
                  for (const CausticsModelName& model : kCausticsModelNames) {
                    if (model.name != text) continue;
                    o.physicalCaustics = model.physical;
                    o.rayDeviationCaustics = model.rayDeviation;
                    return true;
                  }
                  error = "--caustics-model must be " + causticsModelList() + got(text);
                  return false;
                }},
    ValueOption{"--caustics-grid", "N", "wavefront area ratio's water grid, 64..1024 (default 256)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 64, 1024, o.causticsGrid, "--caustics-grid", error);
                }},
    ValueOption{"--caustics-window", "M",
                "wavefront area ratio's window side around the camera (m), 1..1000 (default 32)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, 1.0, 1000.0, o.causticsWindow, "--caustics-window",
                                  "a side in metres in [1, 1000]", error);
                }},
    ValueOption{"--views", "N",
                "render: N side-by-side views (split-screen) in one plugin dispatch, 1..4", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 1, 4, o.views, "--views", error);
                }},
    ValueOption{"--caustics-layers", "N",
                "wavefront area ratio's receiver depth layers, 1..8 (default 4)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 1, 8, o.causticsLayers, "--caustics-layers", error);
                }},
    ValueOption{"--local-water-grid", "N",
                "the pool's or wake's region grid cells per side, 16..2048 (default: the "
                "scene's, 256)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 16, 2048, o.localWaterGrid, "--local-water-grid", error);
                }},
    ValueOption{"--reflected-grid", "N",
                "reflected caustics' water grid cells per side, 64..2048 (default: the "
                "preset's, harbour 1024, else the plugin's 512)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 64, 2048, o.reflectedGrid, "--reflected-grid", error);
                }},
    ValueOption{"--reflected-landing", "WHERE",
                "reflected caustics' rays followed to the view's depth (depth) or to height "
                "layers (layers) (default: the plugin's)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  if (text == "depth" || text == "layers") {
                    o.reflectedLanding = text == "depth" ? 1 : 2;
                    return true;
                  }
                  error = "--reflected-landing must be depth or layers" + got(text);
                  return false;
                }},
    ValueOption{"--volume-method", "HOW",
                "volume caustics' rays drawn as Gaussian beams (beams) or one-pixel lines "
                "(lines) (default: the plugin's, beams)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  if (text == "beams" || text == "lines") {
                    o.volumeMethod = text == "beams" ? 1 : 2;
                    return true;
                  }
                  error = "--volume-method must be beams or lines" + got(text);
                  return false;
                }},
    ValueOption{"--caustics-lookup", "RES",
                "tile model's lookups at full or half (default) resolution", false,
                [](std::string_view text, Options& o, std::string& error) {
                  if (text == "full" || text == "half") {
                    o.causticsLookup = text == "full" ? 1 : 2;
                    return true;
                  }
                  error = "--caustics-lookup must be full or half" + got(text);
                  return false;
                }},
    ValueOption{"--tile-resolution", "N",
                "tile model's irradiance texels per cascade tile side, a power of two in "
                "32..1024 (default 128)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  if (!intIn(text, 32, 1024, o.tileResolution, "--tile-resolution", error))
                    return false;
                  if ((o.tileResolution & (o.tileResolution - 1)) != 0) {
                    error = "--tile-resolution must be a power of two" + got(text);
                    return false;
                  }
                  return true;
                }},
    ValueOption{"--max-receiver-depth", "M",
                "deepest depth (m) the caustic irradiance is computed for, 0.5..1000 "
                "(default: the preset's)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, 0.5, 1000.0, o.maxReceiverDepth, "--max-receiver-depth",
                                  "a depth in metres in [0.5, 1000]", error);
                }},
    ValueOption{"--tile-depth-layers", "N",
                "tile model's depth layers per cascade, 4 (default) or 8", false,
                [](std::string_view text, Options& o, std::string& error) {
                  if (text == "4" || text == "8") {
                    o.tileDepthLayers = text == "4" ? 4 : 8;
                    return true;
                  }
                  error = "--tile-depth-layers must be 4 or 8" + got(text);
                  return false;
                }},
    ValueOption{"--god-rays-resolution", "RES", "full, half or quarter (default)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  const std::array<std::pair<std::string_view, int>, 3> names{
                      {{"full", 1}, {"half", 2}, {"quarter", 4}}};
                  for (const auto& [name, divisor] : names) {
                    if (name != text) continue;
                    o.godRayResolution = divisor;
                    return true;
                  }
                  error = "--god-rays-resolution must be full, half or quarter" + got(text);
                  return false;
                }},
    ValueOption{"--god-ray-samples", "N",
                "god rays' samples per pixel (grid planes crossed), 4..64 (default: the plugin's 16)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, postfx::kGodRaySampleCountRange.min,
                               postfx::kGodRaySampleCountRange.max, o.godRaySamples,
                               "--god-ray-samples", error);
                }},
    ValueOption{"--camera-position", "X,Y,Z",
                "camera position in metres (y up, water at y = 0); default: the preset's", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return point(text, o.cameraPosition, "--camera-position", "metres", error);
                }},
    ValueOption{"--camera-look-at", "X,Y,Z", "point the camera looks at (centred in the image)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return point(text, o.cameraLookAt, "--camera-look-at", "metres", error);
                }},
    ValueOption{"--camera-velocity", "X,Y,Z",
                "render --frames: the camera moves at this many metres per second", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return point(text, o.cameraVelocity, "--camera-velocity", "metres per second",
                               error);
                }},
    ValueOption{"--fov", "DEG", "vertical field of view in degrees, 5..150 (default 60)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, 5.0, 150.0, o.fovDegrees, "--fov",
                                  "a number of degrees in [5, 150]", error);
                }},
    ValueOption{"--sun-azimuth", "DEG",
                "sun azimuth in degrees, 0 toward -z, clockwise seen from above; -360..360", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, -360.0, 360.0, o.sunAzimuthDegrees, "--sun-azimuth",
                                  "a number of degrees in [-360, 360]", error);
                }},
    ValueOption{"--sun-elevation", "DEG", "sun elevation above the horizon in degrees, 1..90",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  // At or below the horizon no sunlight enters the water: the plugin draws
                  // nothing, so such a frame would only show the sky's own light.
                  return doubleIn(text, 1.0, 90.0, o.sunElevationDegrees, "--sun-elevation",
                                  "a number of degrees in [1, 90]", error);
                }},
    ValueOption{"--exposure", "EV",
                "exposure in stops before the tone curve, -16..16 (default: the preset's)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, -16.0, 16.0, o.exposureStops, "--exposure",
                                  "a number of stops in [-16, 16]", error);
                }},
    ValueOption{"--out", "PATH", "output file (or directory for report)", false,
                [](std::string_view text, Options& o, std::string&) {
                  o.out = text;  // checked by the command that writes it, before any work
                  return true;
                }},
    ValueOption{"--frames", "N",
                "bench: measured frames; render: frames of a sequence (one animated GIF with --out "
                "X.gif); view: frames, then quit",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 1, 100000, o.frames, "--frames", error);
                }},
    ValueOption{
        "--fps", "F", "render/view --frames: frames per second of their time, 1..1000 (default 30)",
        false,
        [](std::string_view text, Options& o, std::string& error) {
          return doubleIn(text, 1.0, 1000.0, o.fps, "--fps", "a number in [1, 1000]", error);
        }},
    ValueOption{"--screenshot", "PATH.png",
                "view: the last of --frames (or, on P, the frame shown) as PNG", false,
                [](std::string_view text, Options& o, std::string& error) {
                  // The window holds 8-bit pixels: an .exr would pretend to more.
                  if (!text.ends_with(".png")) {
                    error = "--screenshot must end in .png" + got(text);
                    return false;
                  }
                  o.screenshot = text;  // its directory is checked before the window opens
                  return true;
                }},
    ValueOption{"--json", "FILE", "also write the rows as JSON", false,
                [](std::string_view text, Options& o, std::string&) {
                  o.json = text;
                  return true;
                }},
    ValueOption{"--gpu", "NAMES",
                "bench --work: the GPU classes to estimate for, comma-separated: gtx960m, "
                "rtx3060, rtx4090 or all (default rtx3060)",
                false,
                [](std::string_view text, Options& o, std::string&) {
                  o.gpu = text;  // checked against the class table when the bench starts
                  return true;
                }},
    ValueOption{"--only", "PREFIX", "run only the variant rows whose name starts with PREFIX",
                false,
                [](std::string_view text, Options& o, std::string&) {
                  o.only = text;
                  return true;
                }},
    ValueOption{"--seed", "S", "random seed, a non-negative integer (default 1)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  const auto r = std::from_chars(text.data(), text.data() + text.size(), o.seed);
                  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
                    error = "--seed must be a non-negative integer" + got(text);
                    return false;
                  }
                  return true;
                }},
    ValueOption{
        "--noise", "N", "target p99 noise of the lit pixels, 0.001..0.5 (default 0.05)", false,
        [](std::string_view text, Options& o, std::string& error) {
          return doubleIn(text, 0.001, 0.5, o.noise, "--noise", "a number in [0.001, 0.5]", error);
        }},
    ValueOption{"--kernel", "K", "kernel radius in pixel footprints, 0.25..16 (default 1)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, 0.25, 16.0, o.kernelScale, "--kernel",
                                  "a number in [0.25, 16]", error);
                }},
    ValueOption{"--min-kernel", "M", "smallest kernel radius in metres, 0.001..1 (default 0.01)",
                false,
                [](std::string_view text, Options& o, std::string& error) {
                  return doubleIn(text, 0.001, 1.0, o.minKernelRadius, "--min-kernel",
                                  "a number of metres in [0.001, 1]", error);
                }},
    ValueOption{"--max-batches", "B", "most photon batches, 1..1000 (default 24)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 1, 1000, o.maxBatches, "--max-batches", error);
                }},
    ValueOption{"--threads", "T", "CPU threads, 1..256 (default 2)", false,
                [](std::string_view text, Options& o, std::string& error) {
                  return intIn(text, 1, 256, o.threads, "--threads", error);
                }},
    ValueOption{"--plugin", "P.exr", "the plugin's frame (render --out P.exr)", false,
                [](std::string_view text, Options& o, std::string&) {
                  o.pluginImage = text;
                  return true;
                }},
    ValueOption{"--reference", "R.exr", "the traced frame (reference --out R.exr)", false,
                [](std::string_view text, Options& o, std::string&) {
                  o.referenceImage = text;
                  return true;
                }},
    ValueOption{"--base", "B.exr",
                "the frame without caustics (render --no-caustics --no-object-caustics)", false,
                [](std::string_view text, Options& o, std::string&) {
                  o.baseImage = text;
                  return true;
                }},
    ValueOption{"--flat", "F.exr",
                "flat water's frame (render --caustics-model ray-deviation --tau 0): adds the "
                "pattern-only comparison",
                false,
                [](std::string_view text, Options& o, std::string&) {
                  o.flatImage = text;
                  return true;
                }},
};

const std::array kFlagOptions{
    FlagOption{"--no-caustics", "leave the plugin's seabed caustics out",
               [](Options& o) { o.caustics = false; }},
    FlagOption{"--no-god-rays", "leave the plugin's god rays out",
               [](Options& o) { o.godRays = false; }},
    FlagOption{"--no-object-caustics", "leave the glass and metal objects' caustics out",
               [](Options& o) { o.objectCaustics = false; }},
    FlagOption{"--volume-caustics",
               "add the light the glass objects focus, seen in the water (over the GPU "
               "budget with the object caustics: docs/gpu_cost.md)",
               [](Options& o) { o.volumeCaustics = true; }},
    FlagOption{"--no-volume-caustics", "leave out the light the glass objects focus (the default)",
               [](Options& o) { o.volumeCaustics = false; }},
    FlagOption{"--flat-local-water",
               "give the plugin the pool's or wake's regions flat (compare --flat's frame)",
               [](Options& o) { o.flatLocalWater = true; }},
    FlagOption{"--reflected-caustics",
               "the plugin's reflected caustics above the water on (the harbour's default)",
               [](Options& o) { o.reflectedCaustics = true; }},
    FlagOption{"--no-reflected-caustics", "leave the plugin's reflected caustics out",
               [](Options& o) { o.reflectedCaustics = false; }},
    FlagOption{"--flat-water",
               "give the plugin a flat sea instead of the ocean's waves (compare --flat's frame)",
               [](Options& o) { o.flatWater = true; }},
    FlagOption{"--triplanar-walls", "steep surfaces blend world-axis projections of the water",
               [](Options& o) { o.triplanarWalls = true; }},
    FlagOption{"--freeze-time", "render/view --frames: time stays at --time",
               [](Options& o) { o.freezeTime = true; }},
    FlagOption{"--stereo", "render: a side-by-side stereo pair (eyes 6.4 cm apart), one dispatch",
               [](Options& o) { o.stereo = true; }},
    FlagOption{"--cube-map",
               "render: a cube-map probe (six faces of --width/4, one dispatch) as a 4x3 cross; "
               "--width must be a multiple of 4 and --height is not taken (the cross is "
               "3/4 as tall as wide)",
               [](Options& o) { o.cubeMap = true; }},
    FlagOption{"--no-overlay", "view: no overlay (timings in the title bar, as before it)",
               [](Options& o) { o.overlay = false; }},
    FlagOption{"--quick", "a smoke run in a few minutes", [](Options& o) { o.quick = true; }},
    FlagOption{"--work",
               "bench: each pass's work account (counted in its shaders) and estimated GPU time "
               "(--gpu) beside its llvmpipe time and the CPU model's prediction of it",
               [](Options& o) { o.work = true; }},
};

}  // namespace

std::span<const ValueOption> valueOptions() {
  return kValueOptions;
}
std::span<const FlagOption> flagOptions() {
  return kFlagOptions;
}

const ValueOption* findValueOption(std::string_view flag) {
  for (const ValueOption& option : kValueOptions)
    if (option.flag == flag) return &option;
  return nullptr;
}
const FlagOption* findFlagOption(std::string_view flag) {
  for (const FlagOption& option : kFlagOptions)
    if (option.flag == flag) return &option;
  return nullptr;
}

}  // namespace ocean
