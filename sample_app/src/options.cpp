#include "options.h"

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

bool parseDouble(std::string_view text, double& value) {
  const std::string copy(text);
  char* end = nullptr;
  value = std::strtod(copy.c_str(), &end);
  return !copy.empty() && end == copy.c_str() + copy.size();
}

}  // namespace

std::string usage() {
  return R"(ocean_sample: the ocean scene that hosts the postfx underwater-lighting plugin.

usage:
  ocean_sample render [--preset NAME] [--width W] [--height H] [--time T] [--model FILE]...
                      [--out FILE] [--no-caustics] [--no-god-rays] [--no-object-caustics]
                      [--tau T] [--water-resolution N] [--caustics-model ray-deviation|physical]
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
    if (i + 1 >= argc) {
      error = "option " + std::string(flag) + " needs a value";
      return false;
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
      if (value != "ray-deviation" && value != "seed002" && value != "physical") {
        error =
            "--caustics-model must be ray-deviation or physical, got '" + std::string(value) + "'";
        return false;
      }
      options.physicalCaustics = value == "physical";
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
      if (!parseInt(value, options.waterResolution) || options.waterResolution < 8 ||
          options.waterResolution > 512 ||
          (options.waterResolution & (options.waterResolution - 1)) != 0) {
        options.waterResolution = n;
        error = "--water-resolution must be a power of two in [8, 512], got '" +
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
