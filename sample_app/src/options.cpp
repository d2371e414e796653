#include "options.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>

namespace ocean {
namespace {

bool parseInt(std::string_view text, int& value) {
  const auto result = std::from_chars(text.data(), text.data() + text.size(), value);
  return result.ec == std::errc() && result.ptr == text.data() + text.size();
}

// A number strtod reads whole and without leaving double's range: 1e-400 (which it rounds to 0)
// and 1e400 are refused rather than silently changed.
bool parseDouble(std::string_view text, double& value) {
  const std::string copy(text);
  char* end = nullptr;
  errno = 0;
  value = std::strtod(copy.c_str(), &end);
  return !copy.empty() && end == copy.c_str() + copy.size() && errno != ERANGE;
}

// Options that take a value; anything else that starts with "--" is unknown, value or not.
bool takesValue(std::string_view flag) {
  for (std::string_view known : {"--preset",        "--width",
                                 "--height",        "--time",
                                 "--tau",           "--caustics-model",
                                 "--caustics-grid", "--god-rays-resolution",
                                 "--model",         "--out",
                                 "--json",          "--only",
                                 "--frames",        "--water-resolution",
                                 "--seed",          "--noise",
                                 "--kernel",        "--min-kernel",
                                 "--max-batches",   "--threads",
                                 "--plugin",        "--reference",
                                 "--base"})
    if (flag == known) return true;
  return false;
}

}  // namespace

std::string usage() {
  return R"(ocean_sample: the ocean scene that hosts the postfx underwater-lighting plugin.

usage:
  ocean_sample render [--preset NAME] [--width W] [--height H] [--time T] [--model FILE]...
                      [--out FILE] [--no-caustics] [--no-god-rays] [--no-object-caustics]
                      [--tau T] [--water-resolution 16..512]
                      [--caustics-model ray-deviation|physical]
                      [--caustics-grid N] [--god-rays-resolution full|half|quarter]
                      [--triplanar-walls]
      Renders one frame headless (EGL) and writes it through OpenImageIO: .png (tone-mapped)
      or .exr (linear radiance). Default output: ocean.png.
  ocean_sample view [--preset NAME] [--width W] [--height H] [--model FILE]...
      Opens a window: WASD/QE fly, mouse drag looks, C toggles caustics, G god rays, T pauses time,
      1-4 switch presets, Esc quits.
  ocean_sample bench [--width W] [--height H] [--frames N] [--json FILE] [--only PREFIX]
      Per-pass GPU times (timer queries, median after warm-up) and each pass's ratio to a
      floor pass that reads the same inputs and writes the same outputs with no math.
      Also times each variant: caustics with every cascade everywhere (caustics_all_cascades)
      and with the tri-planar walls (caustics_triplanar_walls), god rays per sample count
      (god_rays_<n>, god_rays_half_<n>, god_rays_quarter_<n>),
      the physical caustics model at grid 64..1024 (caustics_physical_<n>), object caustics
      per map/grid/iterations. --only PREFIX runs just the variants whose name starts with it.
  ocean_sample report [--out DIR] [--quick]
      Error against run time of every method and quality setting: each pass timed (median,
      with its floor) and compared with a CPU reference of the same frame. Writes
      DIR/error_vs_time.csv, .md and .png (default DIR: report). --quick: a smoke run.

  ocean_sample reference [render's scene options] [--out FILE.exr] [--seed S] [--noise N]
                         [--kernel K] [--min-kernel M] [--max-batches B] [--threads T]
      Renders the same frame as `render` with the plugin's seabed caustic light replaced by
      traced caustic light in the same units. The plugin's caustics are switched off; sun
      photons are stratified over the frame's own water texture (read back from the GPU),
      refracted (Snell, Fresnel relative to flat water) and traced against the scene's
      triangles with Embree; the irradiance E at each visible surface point is a density
      estimate with an Epanechnikov kernel on a disc of radius max(K x the pixel's footprint
      (area-matched), M metres) (default K 1, M 0.01). Where the plugin adds
        albedo * E_sun * intensity * exp(-absorption d / u.y) * fade(d) * omega * (n.u) * shadow,
      the reference adds the same with omega * (n.u) * shadow replaced by E * u.y (u: the
      unperturbed refracted sun, d: depth; E = 1 on a horizontal receiver under flat water, so
      flat water gives exactly the plugin's unperturbed light). Hence (reference - frame with
      --no-caustics) compares pixel by pixel with (render - frame with --no-caustics).
      E is the mean of independent photon batches (each a complete stratified launch); its
      noise is the standard error from their scatter over max(E, flat-water E, 0.2). Batches
      are added, at least 8, until the 99th percentile of the lit pixels' noise is below N
      (default 0.05), at most B batches (default 24; the summary says if it did not
      converge). Deterministic for a seed S, on any thread count (T threads, default 2).
      One IOR (the water's mean: the plugin's dispersion is not traced); occlusion is traced
      (no shadow map); no light on surfaces above the water or on the sky. Progress on
      stdout. Writes linear radiance to FILE.exr (default reference.exr) with extra channels
      caustic.E (traced irradiance), caustic.noise and caustic.lit (1: an underwater surface
      that flat-water sunlight reaches unoccluded).
  ocean_sample compare --plugin P.exr --reference R.exr --base B.exr [--out FILE.png]
      P: `render --out P.exr`, R: `reference --out R.exr`, B: `render --no-caustics --out B.exr`,
      same preset, size and time. Over the lit underwater pixels (R's caustic.lit) it prints
      the relative RMSE and Pearson correlation of the added light, luminance of (P - B)
      against luminance of (R - B), and writes FILE.png (default compare.png): top row the
      plugin frame | the reference frame | the frame without caustics (tone-mapped as the
      sample does); bottom row the plugin's added light | the reference's added light | their
      difference (red: plugin brighter, blue: darker), all on one scale (the reference's 99th
      percentile is white).

  ocean_sample --help

caustics models: ray-deviation (default; exp(-tau a^2), a the refracted ray's deviation from
flat water, one lookup per cascade and pixel; "seed002" is its former name) or physical (true
irradiance from the wavefront area ratio, seed 004; --caustics-grid 64..1024, default 256).
Every surface looks the water up where its light entered, along the refracted sun; with
--triplanar-walls steep surfaces blend in seed 002's world-axis projections instead.

--model FILE[@x,y,z][:fit=M|none]: a glTF (.glb/.gltf) added as glass or metal casters. By
default its bounding box is scaled to 1.5 m and set on the sand in a row before the camera;
@x,y,z puts the box's centre at x, z with its bottom y metres above the sand; :fit=M scales its
largest side to M metres (0.01..100), :fit=none keeps the file's size.

presets: seabed (underwater, looking at the seabed), sunward (underwater, looking up toward
the sun), above (above the water looking down), waterline (camera 3 cm above the water).
)";
}

bool parseOptions(int argc, const char* const* argv, Options& options, std::string& error) {
  if (argc < 2) {
    error = "no command given (try --help)";
    return false;
  }
  const std::string_view command = argv[1];
  if (command == "--help" || command == "-h" || command == "help") {
    options.command = Command::Help;
    return true;
  }
  if (command == "render") {
    options.command = Command::Render;
  } else if (command == "view") {
    options.command = Command::View;
  } else if (command == "bench") {
    options.command = Command::Bench;
  } else if (command == "report") {
    options.command = Command::Report;
    options.out = "report";
  } else if (command == "reference") {
    options.command = Command::Reference;
    options.out = "reference.exr";
  } else if (command == "compare") {
    options.command = Command::Compare;
    options.out = "compare.png";
  } else {
    error = "unknown command '" + std::string(command) + "' (try --help)";
    return false;
  }
  for (int i = 2; i < argc; ++i) {
    const std::string_view flag = argv[i];
    if (flag == "--help" || flag == "-h") {
      options.command = Command::Help;
      return true;
    }
    if (flag == "--no-caustics") {
      options.caustics = false;
      continue;
    }
    if (flag == "--no-god-rays") {
      options.godRays = false;
      continue;
    }
    if (flag == "--quick") {
      options.quick = true;
      continue;
    }
    if (flag == "--no-object-caustics") {
      options.objectCaustics = false;
      continue;
    }
    if (flag == "--triplanar-walls") {
      options.triplanarWalls = true;
      continue;
    }
    if (!takesValue(flag)) {
      error = "unknown option '" + std::string(flag) + "' (try --help)";
      return false;
    }
    if (i + 1 >= argc) {
      error = "option " + std::string(flag) + " needs a value";
      return false;
    }
    // Every option but --model (one per glTF file) is given at most once: a second one would
    // otherwise silently win.
    if (flag != "--model") {
      for (int j = 2; j < i; ++j) {
        if (argv[j] == flag) {
          error = "option " + std::string(flag) + " is given twice";
          return false;
        }
      }
    }
    const std::string_view value = argv[++i];
    auto needPositiveSize = [&](int& target, const char* what) {
      if (!parseInt(value, target) || target <= 0 || target > kMaxImageSide) {
        error = std::string(what) + " must be an integer in [1, " + std::to_string(kMaxImageSide) +
                "], got '" + std::string(value) + "'";
        return false;
      }
      return true;
    };
    if (flag == "--preset") {
      options.preset = value;
    } else if (flag == "--width") {
      if (!needPositiveSize(options.width, "--width")) return false;
    } else if (flag == "--height") {
      if (!needPositiveSize(options.height, "--height")) return false;
    } else if (flag == "--time") {
      if (!parseDouble(value, options.timeSeconds) || !std::isfinite(options.timeSeconds)) {
        error = "--time must be a finite number of seconds, got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--tau") {
      if (!parseDouble(value, options.tau) || !(options.tau >= 0.0 && options.tau <= 1e6)) {
        error = "--tau must be a number in [0, 1e6], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--caustics-model") {
      if (value != "tile" && value != "ray-deviation" && value != "seed002" &&
          value != "physical") {
        error = "--caustics-model must be tile, ray-deviation or physical, got '" +
                std::string(value) + "'";
        return false;
      }
      options.physicalCaustics = value == "physical";
      options.rayDeviationCaustics = value == "ray-deviation" || value == "seed002";
    } else if (flag == "--caustics-grid") {
      if (!parseInt(value, options.causticsGrid) || options.causticsGrid < 64 ||
          options.causticsGrid > 1024) {
        error =
            "--caustics-grid must be an integer in [64, 1024], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--god-rays-resolution") {
      if (value == "full") {
        options.godRayResolution = 1;
      } else if (value == "half") {
        options.godRayResolution = 2;
      } else if (value == "quarter") {
        options.godRayResolution = 4;
      } else {
        error =
            "--god-rays-resolution must be full, half or quarter, got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--seed") {
      const auto result = std::from_chars(value.data(), value.data() + value.size(), options.seed);
      if (result.ec != std::errc() || result.ptr != value.data() + value.size()) {
        error = "--seed must be a non-negative integer, got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--noise") {
      if (!parseDouble(value, options.noise) || !(options.noise >= 0.001 && options.noise <= 0.5)) {
        error = "--noise must be a number in [0.001, 0.5], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--kernel") {
      if (!parseDouble(value, options.kernelScale) ||
          !(options.kernelScale >= 0.25 && options.kernelScale <= 16.0)) {
        error = "--kernel must be a number in [0.25, 16], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--min-kernel") {
      if (!parseDouble(value, options.minKernelRadius) ||
          !(options.minKernelRadius >= 0.001 && options.minKernelRadius <= 1.0)) {
        error = "--min-kernel must be a number of metres in [0.001, 1], got '" +
                std::string(value) + "'";
        return false;
      }
    } else if (flag == "--max-batches") {
      if (!parseInt(value, options.maxBatches) || options.maxBatches < 1 ||
          options.maxBatches > 1000) {
        error = "--max-batches must be an integer in [1, 1000], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--threads") {
      if (!parseInt(value, options.threads) || options.threads < 1 || options.threads > 256) {
        error = "--threads must be an integer in [1, 256], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--plugin") {
      options.pluginImage = value;
    } else if (flag == "--reference") {
      options.referenceImage = value;
    } else if (flag == "--base") {
      options.baseImage = value;
    } else if (flag == "--model") {
      options.models.emplace_back(value);
    } else if (flag == "--out") {
      options.out = value;
    } else if (flag == "--json") {
      options.json = value;
    } else if (flag == "--only") {
      options.only = value;
    } else if (flag == "--frames") {
      if (!parseInt(value, options.frames) || options.frames < 1 || options.frames > 100000) {
        error = "--frames must be an integer in [1, 100000], got '" + std::string(value) + "'";
        return false;
      }
    } else if (flag == "--water-resolution") {
      const int n = options.waterResolution;
      // 16 at least: the scene's cascades (250, 37 and 5.3 m tiles) hand over between bands
      // only where the finer tile is more than 2/N of the coarser one (the water module's rule).
      if (!parseInt(value, options.waterResolution) || options.waterResolution < 16 ||
          options.waterResolution > 512 ||
          (options.waterResolution & (options.waterResolution - 1)) != 0) {
        options.waterResolution = n;
        error = "--water-resolution must be a power of two in [16, 512], got '" +
                std::string(value) + "'";
        return false;
      }
    } else {
      error = "unknown option '" + std::string(flag) + "' (try --help)";
      return false;
    }
  }
  return true;
}

}  // namespace ocean
