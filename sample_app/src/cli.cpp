// ocean_sample's command line on CLI11: which command offers which option, the help of each,
// and the one-line errors. What each option means and how its value is checked is in
// option_values.cpp; CLI11 only splits the command line, so every refusal reads the same
// whichever step finds it.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <map>
#include <utility>

#include "option_values.h"
#include "options.h"

namespace ocean {
namespace {

// The options of the scene a frame is rendered from (render, view, bench, report, reference).
constexpr std::string_view kSceneOptions[] = {"--preset",
                                              "--width",
                                              "--height",
                                              "--time",
                                              "--model",
                                              "--model-file",
                                              "--model-limits",
                                              "--light",
                                              "--water-resolution",
                                              "--no-caustics",
                                              "--no-god-rays",
                                              "--no-object-caustics",
                                              "--volume-caustics",
                                              "--no-volume-caustics",
                                              "--volume-method",
                                              "--flat-local-water",
                                              "--reflected-caustics",
                                              "--no-reflected-caustics",
                                              "--flat-water",
                                              "--reflected-grid",
                                              "--reflected-landing",
                                              "--local-water-grid",
                                              "--tau",
                                              "--caustics-model",
                                              "--caustics-grid",
                                              "--caustics-window",
                                              "--caustics-layers",
                                              "--caustics-lookup",
                                              "--tile-resolution",
                                              "--max-receiver-depth",
                                              "--tile-depth-layers",
                                              "--god-rays-resolution",
                                              "--god-ray-samples",
                                              "--triplanar-walls",
                                              "--camera-position",
                                              "--camera-look-at",
                                              "--fov",
                                              "--sun-azimuth",
                                              "--sun-elevation",
                                              "--exposure"};

constexpr std::string_view kSceneFooter = R"(
presets: shallow (the default: a calm sea over a reef 3 m deep, shown with 512 tile texels,
full-resolution lookups and irradiance layers to 5 m), seabed (underwater, looking at the
seabed), sunward (underwater, looking up toward the sun), above (above the water looking
down), waterline (camera 3 cm above the water), torch (underwater at night, a diver's torch
shining through the glass sphere onto the sand), pool (a tiled pool on land after webgl-water:
a ripple simulation with drops and a ball, the plugin's local water; click the water in view to
drop), wake (a ball towed across a calm sea, its wake simulated and added to the sea),
harbour (a calm harbour in a low sun: the waves' reflected light on a pier's underside, a quay
wall and a moored boat's side, the plugin's reflected caustics).
--camera-position and --camera-look-at replace the preset's camera (either alone keeps the
other from the preset); the look-at point is centred in the image and must not be straight
above or below the camera. --sun-azimuth/--sun-elevation replace the preset's sun.

--reflected-caustics and --no-reflected-caustics turn the plugin's reflected caustics above the
water (the waves' mirrored sunlight on what faces the water from above it) on or off over the
preset's choice: on in harbour, off in the others. --flat-water hands the plugin a flat sea
(zero slopes and heights) instead of the ocean's waves, the sample's own water unchanged: flat
water's frame for compare --flat.

--light point:X,Y,Z:I[:RANGE] or spot:X,Y,Z:DX,DY,DZ:I:CONE[:SOFTNESS[:RANGE]] adds a light to
the preset's (at most 4 in all): position in metres, the spot's axis (any length), intensity I
or R,G,B (the irradiance it gives at 1 m facing it, in the sample's HDR units: the sun's is ~3),
the spot's full cone angle in degrees (0, 180), the share of its half-angle faded at the edge
[0, 1] (default 0.3) and the range in metres [0, 1e6] (default 20: farther casters make no
caustics from it). The sample lights the scene with it (inverse square, the cone, water's
extinction, a shadow map from the light) and the plugin adds its caustics through glass and
metal.

caustics models: tile (default; true caustic irradiance, computed each frame per water cascade
over its periodic tile at a few depths, each cascade's light moved by the coarser ones'
refraction; any distance, one small pre-pass), ray-deviation (exp(-tau a^2), a the refracted
ray's deviation from flat water: a pattern without absolute scale; "seed002" is its former
name) or physical (irradiance from the wavefront area ratio in a window around the camera;
--caustics-grid 64..1024, default 256). Every surface looks the water up where its light
entered, along the refracted sun; with --triplanar-walls steep surfaces blend in world-axis
projections instead (ray-deviation only).

--model FILE[@x,y,z][:fit=M|none]: a glTF (.glb/.gltf) added as glass or metal casters. By
default its bounding box is scaled to 1.5 m and set in a row across the preset camera's view,
on the sand (or, where the view passes above it, under the water on the view's centre line);
@x,y,z puts the box's centre at x, z with its bottom y metres above the sand; :fit=M scales its
largest side to M metres (0.01..100), :fit=none keeps the file's size. Glass is a material
with KHR_materials_transmission and metallic < 0.5 (transmission x (1 - metallic) weighs its
caustic, the base colour tints it, KHR_materials_volume absorbs along the path, thickness 0 is
a thin wall that does not focus, roughness widens it); metal (metallic >= 0.5) and ior 0 are
mirrors. Draco and meshopt compression are decoded; a base-colour texture (embedded, a data:
URI or a file beside the model) is averaged into the colour, other textures are not used (a
warning names them). --model-file PATH adds a file like --model with PATH taken literally, for
names with '@' or ':fit=' in them (placed in the row at the default size, after the --model
files); with --model such a name works when a position or fit follows (the last '@' and ':fit='
are the options').

Each file is held to a work budget, checked from its own counts before anything is expanded:
4194304 triangles after instancing, 16384 instances (one per primitive per node copy), 65536
nodes, 1 GiB once expanded (buffers, meshes, instances), 1048576 values in its JSON and
33554432 texture pixels decoded (each image once, size from its header). A file over it is
refused naming each limit with its count; --model-limits
triangles=N,instances=N,nodes=N,bytes=N,json-values=N,pixels=N (any of them, N up to 2^40,
k/M/G suffixes) raises them.)";

// Flags that say opposite things: given both, the one applied last would win unseen.
constexpr std::pair<std::string_view, std::string_view> kContradictingFlags[] = {
    {"--reflected-caustics", "--no-reflected-caustics"},
    {"--volume-caustics", "--no-volume-caustics"}};

struct CommandSpec {
  std::string_view name;
  Command command;
  std::string_view summary;               // one line, in the list of commands
  std::string_view description;           // the command's own --help, wrapped
  std::vector<std::string_view> options;  // beside the scene options where `scene` is set
  bool scene;
  std::string_view out;  // --out's default
  int frames;            // --frames' default
  std::string_view footer;
};

const std::vector<CommandSpec>& commands() {
  static const std::vector<CommandSpec> all = {
      {"render",
       Command::Render,
       "one frame (or a sequence) headless to PNG/EXR",
       "Renders one frame headless (EGL) and writes it through OpenImageIO: .png (tone-mapped) "
       "or .exr (linear radiance). With --frames N > 1: N frames with time running at --fps, "
       "written as OUT with the frame number before the extension (ocean_0000.png, ...), the "
       "camera moving at --camera-velocity (with --freeze-time only the camera moves), and each "
       "frame's change from the one before "
       "printed.",
       {"--out", "--frames", "--fps", "--camera-velocity", "--freeze-time", "--views", "--cube-map",
        "--stereo"},
       true,
       "ocean.png",
       1,
       kSceneFooter},
      {"view",
       Command::View,
       "the scene in a window",
       "Opens a window: WASD/QE fly, mouse drag looks, C toggles caustics, G god rays, T pauses "
       "time, 1-4 switch presets, H hides the overlay, Esc quits. The overlay shows each pass's "
       "GPU time as the plugin reports it and edits every feature's settings live; a value the "
       "plugin refuses shows its message and the frame keeps the last accepted settings. With "
       "--frames N it draws N frames on a fixed clock (--fps) and quits; --screenshot saves the "
       "last one as shown (P saves the frame shown there too).",
       {"--frames", "--fps", "--freeze-time", "--screenshot", "--no-overlay"},
       true,
       "",
       0,
       kSceneFooter},
      {"bench",
       Command::Bench,
       "per-pass GPU time and ratio to the floor pass",
       "Per-pass GPU times (timer queries, median after warm-up) and each pass's ratio to a "
       "floor pass that reads the same inputs and writes the same outputs with no math; also "
       "each variant (caustics_all_cascades, caustics_triplanar_walls, god_rays[_half|_quarter]"
       "_<n>, wavefront_area_ratio_<n>[_tile_irradiance|_caustics], "
       "object_caustics_<map>_<grid>_<iterations>).",
       {"--frames", "--json", "--only", "--work", "--gpu"},
       true,
       "",
       60,
       kSceneFooter},
      {"report",
       Command::Report,
       "error against GPU time of every method and setting",
       "Error against run time of every method and quality setting: each pass timed (median, "
       "with its floor) and compared with a CPU reference of the same frame. Writes "
       "DIR/error_vs_time.csv, .md and .png (default DIR: report). The size is the report's "
       "own (320x180, --quick 160x90). Also the temporal stability of every pass against its "
       "reference's (DIR/temporal_stability.csv and .md, 160x90; --quick leaves the "
       "references out); --only stability writes that table alone, --only local-water the "
       "pool's grid sweep against its trace (DIR/local_water.*), --only reflected the "
       "harbour's reflected caustics against its trace (DIR/reflected.*); --max-batches B caps "
       "their traces' batches.",
       {"--out", "--quick", "--only", "--max-batches"},
       true,
       "report",
       60,
       kSceneFooter},
      {"reference",
       Command::Reference,
       "the frame with its caustic light traced (EXR)",
       "Renders the same frame as render with the plugin's caustic light replaced by "
       "traced caustic light in the same units (sun photons through the frame's own water "
       "texture against the scene's triangles, Embree, and on through its glass and metal "
       "casters, from the sun and from each local light under the water, unless "
       "--no-object-caustics; an Epanechnikov density estimate on a "
       "disc of max(K x the pixel's footprint, M metres)). Batches are added, at least 8, until "
       "the 99th percentile of the lit pixels' noise is below N, at most B. Deterministic for a "
       "seed on any thread count. Writes linear radiance to OUT.exr with channels caustic.E, "
       "caustic.noise, caustic.lit, caustic.objectE (light through the casters, flat water = 1) "
       "and caustic.objectRegion (the casters' shadows and where that light falls); with the "
       "reflected light (the harbour, --reflected-caustics) caustic.reflectedE (flat water's "
       "mirror light on a horizontal receiver = 1), caustic.reflectedNoise and "
       "caustic.reflectedLit (the pixels flat water's mirror light reaches).",
       {"--out", "--seed", "--noise", "--kernel", "--min-kernel", "--max-batches", "--threads"},
       true,
       "reference.exr",
       60,
       kSceneFooter},
      {"compare",
       Command::Compare,
       "plugin frame against traced frame: error, correlation, side by side",
       "P: render --out P.exr, R: reference --out R.exr, B: render --no-caustics "
       "--no-object-caustics --out B.exr "
       "(the same scene options for all three, --caustics-model too: each model lights its god "
       "rays from its own field, and shafts that differ would count as caustic light). Over R's "
       "lit underwater pixels it prints the relative "
       "RMSE and Pearson correlation of the added light (P - B against R - B), the same over "
       "R's object-caustics region with the flux ratio, and writes OUT "
       "(default compare.png): the three frames above, the two added lights and their "
       "difference below (red: plugin brighter, blue: darker). With F (--flat F.exr: "
       "render --caustics-model ray-deviation --tau 0 --no-object-caustics, flat water's "
       "frame) it also compares "
       "the pattern alone: each added light divided by F - B where F - B is at least a quarter "
       "of its median (what both share, albedo, N.L, shadow, absorption, divides out), and "
       "the patterns' power per octave of period over one square patch (too soft, too sharp, "
       "or a narrow peak: rings the trace lacks); a third row shows the two patterns. Where R "
       "traced the light the water reflects up (caustic.reflectedLit: the harbour, "
       "--reflected-caustics), the same over the pixels above the water flat water's mirror "
       "light reaches (B: --no-reflected-caustics; F: --flat-water).",
       {"--plugin", "--reference", "--base", "--flat", "--out"},
       false,
       "compare.png",
       60,
       ""},
  };
  return all;
}

// The options a command offers: its own, then the scene's, each once.
std::vector<std::string_view> offered(const CommandSpec& spec) {
  std::vector<std::string_view> flags = spec.options;
  if (spec.scene) {
    for (std::string_view flag : kSceneOptions) {
      // report sizes its frames itself: a --width there would be silently ignored.
      if (spec.command == Command::Report && (flag == "--width" || flag == "--height")) continue;
      if (std::find(flags.begin(), flags.end(), flag) == flags.end()) flags.push_back(flag);
    }
  }
  return flags;
}

// `text` broken into lines of at most 94 characters at spaces.
std::string wrapped(std::string_view text) {
  std::string out, line;
  size_t start = 0;
  while (start < text.size()) {
    size_t end = text.find(' ', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > 94) {
      out += line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + std::string(word);
    start = end + 1;
  }
  return out + line + "\n";
}

// What CLI11 collected for one command, before any value is checked.
struct Collected {
  std::map<std::string_view, std::vector<std::string>> values;
  std::map<std::string_view, bool> flags;
};

void addOptions(CLI::App& app, const CommandSpec& spec, Collected& collected) {
  for (std::string_view flag : offered(spec)) {
    if (const ValueOption* option = findValueOption(flag)) {
      app.add_option(std::string(flag), collected.values[flag], std::string(option->help))
          ->type_name(std::string(option->typeName))
          ->expected(1)
          ->allow_extra_args(false)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    } else if (const FlagOption* switchOption = findFlagOption(flag)) {
      app.add_flag(std::string(flag), collected.flags[flag], std::string(switchOption->help));
    }
  }
  app.footer(wrapped(spec.description) + "\n" + std::string(spec.footer));
  // Unknown arguments are named by parseCommandLine in our own words.
  app.allow_extras();
}

std::string oneLine(std::string text) {
  while (!text.empty() && text.back() == '\n') text.pop_back();
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

ParsedCommandLine failure(std::string message) {
  ParsedCommandLine parsed;
  parsed.outcome = ParsedCommandLine::Outcome::Error;
  parsed.text = oneLine(std::move(message));
  return parsed;
}

}  // namespace

ParsedCommandLine parseCommandLine(int argc, const char* const* argv) {
  if (argc < 2) return failure("no command given (try --help)");
  CLI::App app("ocean_sample: the ocean scene that hosts the postfx underwater-lighting plugin.",
               "ocean_sample");
  app.require_subcommand(0, 1);
  app.allow_extras();  // options before the command: named below in our own words
  std::map<std::string_view, Collected> collected;
  for (const CommandSpec& spec : commands()) {
    CLI::App* sub = app.add_subcommand(std::string(spec.name), std::string(spec.summary));
    addOptions(*sub, spec, collected[spec.name]);
  }
  // After the commands, which would otherwise inherit it.
  app.footer("Each command has its own help: ocean_sample COMMAND --help.");
  const std::string_view first = argv[1];
  if (first == "help") {
    ParsedCommandLine parsed;
    parsed.outcome = ParsedCommandLine::Outcome::Help;
    parsed.text = app.help();
    return parsed;
  }
  const bool known = std::any_of(commands().begin(), commands().end(),
                                 [&](const CommandSpec& c) { return c.name == first; });
  if (!first.starts_with("-") && !known)
    return failure("unknown command '" + std::string(first) + "' (try --help)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    ParsedCommandLine parsed;
    parsed.outcome = ParsedCommandLine::Outcome::Help;
    const auto chosen = app.get_subcommands();
    parsed.text = chosen.empty() ? app.help() : chosen.front()->help();
    return parsed;
  } catch (const CLI::ParseError& e) {
    // "--width: 1 required W missing" is CLI11's way of saying the value is missing.
    const std::string what = e.what();
    const size_t colon = what.find(':');
    if (e.get_name() == "ArgumentMismatch" && colon != std::string::npos)
      return failure("option " + what.substr(0, colon) + " needs a value");
    return failure(what + " (try --help)");
  }
  // Arguments before the command belong to no command.
  const auto early = app.remaining();
  if (!early.empty()) {
    const std::string flag = early.front().substr(0, early.front().find('='));
    return failure(findValueOption(flag) || findFlagOption(flag)
                       ? "option " + flag + " goes after the command (try --help)"
                       : "unknown option '" + flag + "' (try --help)");
  }
  const auto chosen = app.get_subcommands();
  if (chosen.empty()) return failure("no command given (try --help)");
  const CLI::App& sub = *chosen.front();
  const CommandSpec& spec =
      *std::find_if(commands().begin(), commands().end(),
                    [&](const CommandSpec& c) { return c.name == sub.get_name(); });

  ParsedCommandLine parsed;
  Options& options = parsed.options;
  options.command = spec.command;
  if (!spec.out.empty()) options.out = std::string(spec.out);
  options.frames = spec.frames;
  const Collected& given = collected.at(spec.name);
  // In the order of the table, so the first refusal is the same whatever order the user typed.
  for (const ValueOption& option : valueOptions()) {
    const auto found = given.values.find(option.flag);
    if (found == given.values.end()) continue;
    const std::vector<std::string>& texts = found->second;
    if (texts.size() > 1 && !option.repeatable)
      return failure("option " + std::string(option.flag) + " is given twice");
    std::string error;
    for (const std::string& text : texts) {
      if (!option.apply(text, options, error)) return failure(error);
    }
  }
  for (const FlagOption& option : flagOptions()) {
    const auto found = given.flags.find(option.flag);
    if (found != given.flags.end() && found->second) option.apply(options);
  }
  const auto set = [&](std::string_view flag) {
    const auto found = given.flags.find(flag);
    return found != given.flags.end() && found->second;
  };
  for (const auto& [one, other] : kContradictingFlags) {
    if (set(one) && set(other))
      return failure("options " + std::string(one) + " and " + std::string(other) +
                     " contradict each other (give one)");
  }
  // After the values: in "--width --model x" the news is that --width got "--model".
  const std::string help = " (try ocean_sample " + std::string(spec.name) + " --help)";
  for (const std::string& extra : sub.remaining()) {
    if (extra.starts_with("-")) {
      const std::string flag = extra.substr(0, extra.find('='));
      const bool elsewhere = findValueOption(flag) || findFlagOption(flag);
      return failure((elsewhere
                          ? "option " + flag + " is not one of " + std::string(spec.name) + "'s"
                          : "unknown option '" + flag + "'") +
                     help);
    }
    return failure("unexpected argument '" + extra + "'" + help);
  }
  parsed.outcome = ParsedCommandLine::Outcome::Run;
  return parsed;
}

}  // namespace ocean
