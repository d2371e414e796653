// Bad input to `ocean_sample render`: one line naming the problem on stderr, non-zero exit, no
// crash, no output file.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <nlohmann/json.hpp>

#include "image_output.h"

#include "gltf_test_files.h"

#include <scene/gltf_loader.h>
#include <scene/gltf_writer.h>

namespace {

namespace fs = std::filesystem;

bool imageSize(const fs::path& path, int& width, int& height) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return false;
  width = in->spec().width;
  height = in->spec().height;
  return true;
}

// One named channel of an EXR, or nothing when the file or the channel is missing.
std::vector<float> exrChannel(const fs::path& path, const std::string& name) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  const OIIO::ImageSpec& spec = in->spec();
  const int c = spec.channelindex(name);
  if (c < 0) return {};
  std::vector<float> values(size_t(spec.width) * size_t(spec.height));
  if (!in->read_image(0, 0, c, c + 1, OIIO::TypeDesc::FLOAT, values.data())) return {};
  return values;
}

struct RunResult {
  int exitCode = -1;
  bool signalled = false;
  std::string stderrText;
  std::string stdoutText;
};

// stderr goes to a file in `scratch`: tests run as parallel processes, each with its own.
RunResult runSample(const std::string& arguments, const fs::path& scratch) {
  const fs::path errFile = scratch / "stderr.txt", outFile = scratch / "stdout.txt";
  const std::string command = std::string(OCEAN_SAMPLE_EXE) + " " + arguments + " 2>" +
                              errFile.string() + " >" + outFile.string();
  const int status = std::system(command.c_str());
  RunResult result;
  result.signalled = WIFSIGNALED(status);
  result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(errFile);
  std::ostringstream text;
  text << err.rdbuf();
  result.stderrText = text.str();
  fs::remove(errFile);
  std::ifstream out(outFile);
  std::ostringstream outText;
  outText << out.rdbuf();
  result.stdoutText = outText.str();
  fs::remove(outFile);
  return result;
}

class SampleCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("ocean_cli_" + std::to_string(::getpid()) + "_" + test->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs a command that must fail (render unless `command` says otherwise), and checks the
  // contract.
  void expectRejected(const std::string& arguments, const std::string& mentions,
                      const std::string& command = "render",
                      const std::string& outName = "out.png") {
    const fs::path out = dir_ / outName;
    // compare renders nothing, so it offers no scene options (each command its own).
    const std::string size =
        command == "compare" ? " " : " --width 64 --height 36 --water-resolution 16 ";
    const RunResult result = runSample(command + size + arguments + " --out " + out.string(), dir_);
    EXPECT_FALSE(result.signalled) << arguments;
    EXPECT_NE(result.exitCode, 0) << arguments;
    EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1)
        << "expected one line, got: " << result.stderrText;
    EXPECT_NE(result.stderrText.find(mentions), std::string::npos)
        << "message should mention '" << mentions << "': " << result.stderrText;
    EXPECT_FALSE(fs::exists(out)) << "a failed " << command << " left an output file";
    for (const auto& entry : fs::directory_iterator(dir_)) {
      if (entry.path().filename().string().find("partial") != std::string::npos) {
        ADD_FAILURE() << "partial file left: " << entry.path();
      }
    }
  }

  // The mean frame-to-frame change of a short sequence at 30 and at 480 fps: a frame that
  // follows time and camera smoothly changes about 16 times less per 16 times shorter step.
  void expectChangeFollowsTheStep(const std::string& arguments);

  fs::path writeFile(const std::string& name, const std::string& bytes) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << bytes;
    return path;
  }

  fs::path dir_;
};

TEST_F(SampleCli, UnknownPreset) {
  expectRejected("--preset lagoon", "lagoon");
}
TEST_F(SampleCli, ZeroSize) {
  expectRejected("--width 0", "--width");
}
TEST_F(SampleCli, AbsurdSize) {
  expectRejected("--height 99999999", "--height");
}
TEST_F(SampleCli, NotANumber) {
  expectRejected("--time nan", "--time");
}
TEST_F(SampleCli, UnknownGodRayResolution) {
  expectRejected("--god-rays-resolution eighth", "--god-rays-resolution");
  expectRejected("--tile-resolution 100", "--tile-resolution must be a power of two");
  expectRejected("--tile-resolution 2048", "--tile-resolution");
  expectRejected("--max-receiver-depth 0.1", "--max-receiver-depth");
  expectRejected("--caustics-window 0.5", "--caustics-window");
  expectRejected("--caustics-window nan", "--caustics-window");
  expectRejected("--caustics-layers 9", "--caustics-layers");
  expectRejected("--caustics-layers 0", "--caustics-layers");
  expectRejected("--max-receiver-depth nan", "--max-receiver-depth");
  expectRejected("--tile-depth-layers 6", "--tile-depth-layers must be 4 or 8");
}
TEST_F(SampleCli, MissingModel) {
  expectRejected("--model " + (dir_ / "missing.glb").string(), "missing.glb");
}
TEST_F(SampleCli, GarbageModel) {
  expectRejected("--model " + writeFile("garbage.glb", std::string(300, 'x')).string(),
                 "garbage.glb");
}
TEST_F(SampleCli, TruncatedModel) {
  std::ifstream asset(std::string(OCEAN_ASSETS) + "/glass_sphere.glb", std::ios::binary);
  std::ostringstream buffer;
  buffer << asset.rdbuf();
  std::string bytes = buffer.str();
  ASSERT_GT(bytes.size(), 200u);
  bytes.resize(bytes.size() / 2);
  expectRejected("--model " + writeFile("truncated.glb", bytes).string(), "truncated.glb");
}
// A directory, a FIFO and a device as --model are named for what they are; the FIFO
// is never waited on (a hang trips the alarm and fails the test).
TEST_F(SampleCli, ModelThatIsNotARegularFile) {
  ::alarm(60);
  expectRejected("--model " + dir_.string(), "is a directory");
  ASSERT_EQ(::mkfifo((dir_ / "pipe.glb").c_str(), 0600), 0);
  expectRejected("--model " + (dir_ / "pipe.glb").string(), "FIFO");
  expectRejected("--model /dev/zero", "is a device");
  ::alarm(0);
}
TEST_F(SampleCli, MalformedModelPlacement) {
  expectRejected("--model a.glb@1,2", "position must be @x,y,z");
  expectRejected("--model a.glb:fit=0", "fit must be a size in metres");
}

// A valid file with a node hidden by scale 0 and a glass node whose
// attenuation the plugin refuses still renders; each left-out node is a warning naming the
// file and the node.
TEST_F(SampleCli, ModelWithNodesThePluginCannotUseStillRenders) {
  gltf_test_files::TriangleJson json;
  // Mesh 0 is the dense glass inserted below, mesh 1 the plain (metal by glTF default) one.
  json.nodes = R"({"mesh": 1, "name": "plate"}, {"mesh": 1, "name": "lid", "scale": [0, 0, 0]},
      {"mesh": 0, "name": "ink", "translation": [0, 0.5, 0]})";
  json.sceneNodes = "0, 1, 2";
  json.top = R"("materials": [{"name": "dense", "pbrMetallicRoughness": {"metallicFactor": 0},
      "extensions": {"KHR_materials_transmission":
      {"transmissionFactor": 1}, "KHR_materials_volume": {"thicknessFactor": 0.1,
      "attenuationDistance": 1e-6,
      "attenuationColor": [0.01, 0.01, 0.01]}}}], )";
  std::string text = json.text();
  // A first mesh: the same triangle in the dense glass.
  const std::string meshes = "\"meshes\": [";
  text.insert(text.find(meshes) + meshes.size(),
              "{\"name\": \"glass\", \"primitives\": [{\"attributes\": {\"POSITION\": 0}, "
              "\"material\": 0}]}, ");
  const fs::path model = writeFile("odd.gltf", text);
  const fs::path out = dir_ / "odd.png";
  const RunResult result =
      runSample("render --width 64 --height 36 --water-resolution 16 --model " + model.string() +
                    " --out " + out.string(),
                dir_);
  EXPECT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_TRUE(fs::exists(out));
  EXPECT_NE(result.stderrText.find("warning: " + model.string() + ": node 1 'lid' left out"),
            std::string::npos)
      << result.stderrText;
  EXPECT_NE(result.stderrText.find(model.string() +
                                   " node 'ink': casts no caustics, material 'dense' absorbs"),
            std::string::npos)
      << result.stderrText;
}

// A file whose name has the placement syntax in it ('@', ':fit=') loads through
// --model-file, which takes the path literally; --model reads the same name as a placement.
TEST_F(SampleCli, ModelFileTakesItsPathLiterally) {
  std::ifstream asset(std::string(OCEAN_ASSETS) + "/glass_sphere.glb", std::ios::binary);
  std::ostringstream buffer;
  buffer << asset.rdbuf();
  const fs::path model = writeFile("a@b:fit=2.glb", buffer.str());
  expectRejected("--model " + model.string(), "fit must be a size in metres");
  const fs::path out = dir_ / "literal.png";
  const RunResult result =
      runSample("render --width 64 --height 36 --water-resolution 16 --model-file " +
                    model.string() + " --out " + out.string(),
                dir_);
  EXPECT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_TRUE(fs::exists(out));
}

// A model over the work budget is refused naming the limit, its count and
// the option that raises it; a bad --model-limits is refused before any work.
TEST_F(SampleCli, ModelOverTheWorkBudget) {
  const std::string sphere = std::string(OCEAN_ASSETS) + "/glass_sphere.glb";
  expectRejected("--model " + sphere + " --model-limits triangles=10,nodes=64",
                 "triangles after instancing (limit 10); refused before it is expanded (raise "
                 "with --model-limits triangles=N)");
  expectRejected("--model-limits triangles=0", "--model-limits triangles must be");
  expectRejected("--model-limits colours=3", "'colours=3' is not KEY=N");
  expectRejected("--model-limits bytes=2T", "--model-limits bytes must be");
  // The JSON's values and the texture pixels decoded are keys like the others.
  expectRejected("--model " + sphere + " --model-limits json-values=50",
                 "more than 50 JSON values (limit 50); refused before it is expanded (raise "
                 "with --model-limits json-values=N)");
  expectRejected("--model-limits pixels=0", "--model-limits pixels must be");
}

TEST_F(SampleCli, UnwritableOutputDirectory) {
  const RunResult result =
      runSample("render --width 64 --height 36 --out /nonexistent-dir/ocean.png", dir_);
  EXPECT_NE(result.exitCode, 0);
  EXPECT_NE(result.stderrText.find("nonexistent-dir"), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists("/nonexistent-dir/ocean.png"));
}
TEST_F(SampleCli, UnknownExtension) {
  const fs::path out = dir_ / "ocean.bmpx";
  const RunResult result = runSample("render --width 64 --height 36 --out " + out.string(), dir_);
  EXPECT_NE(result.exitCode, 0);
  EXPECT_FALSE(fs::exists(out));
}

// Each of these once failed late (after the whole render, naming an internal file),
// or misleadingly, or not at all. Each is now one up-front line naming the option.
TEST_F(SampleCli, WaterResolutionTheSceneCannotUse) {
  const RunResult result = runSample("render --width 64 --height 36 --water-resolution 8", dir_);
  EXPECT_NE(result.exitCode, 0);
  EXPECT_NE(result.stderrText.find("--water-resolution must be a power of two in [16, 512]"),
            std::string::npos)
      << result.stderrText;
}
TEST_F(SampleCli, TrailingUnknownFlagIsUnknownNotMissingAValue) {
  const RunResult result = runSample("render --width 64 --bogus", dir_);
  EXPECT_NE(result.exitCode, 0);
  EXPECT_NE(result.stderrText.find("unknown option '--bogus'"), std::string::npos)
      << result.stderrText;
}
TEST_F(SampleCli, TauThatUnderflowsIsRefused) {
  expectRejected("--tau 1e-400", "--tau");
}
TEST_F(SampleCli, DuplicatedOptionIsRefused) {
  expectRejected("--width 32", "--width is given twice");
}
TEST_F(SampleCli, OutputWithoutAFileName) {
  const RunResult result =
      runSample("render --width 64 --height 36 --out " + (dir_ / ".png").string(), dir_);
  EXPECT_NE(result.exitCode, 0);
  EXPECT_NE(result.stderrText.find("no file name"), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists(dir_ / ".png"));
}
TEST_F(SampleCli, OutputDirectoryThatRefusesFilesFailsUpFront) {
  // /proc takes no new files, even from root (for whom access(W_OK) says yes, so the probe file
  // is what refuses it); an ordinary user is refused by the directory check before that.
  const RunResult result = runSample("render --width 64 --height 36 --out /proc/o.exr", dir_);
  EXPECT_NE(result.exitCode, 0);
  const bool probeRefused =
      result.stderrText.find("cannot create '/proc/o.exr'") != std::string::npos;
  const bool directoryRefused =
      result.stderrText.find("output directory '/proc' does not exist or is not writable") !=
      std::string::npos;
  EXPECT_TRUE(probeRefused || directoryRefused) << result.stderrText;
  EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1)
      << "one line: " << result.stderrText;
  EXPECT_EQ(result.stderrText.find("partial"), std::string::npos)
      << "names the internal temporary: " << result.stderrText;
}

// The camera and sun flags are checked up front like every other value.
TEST_F(SampleCli, CameraAndSunValuesAreChecked) {
  expectRejected("--fov 0", "--fov must be a number of degrees in [5, 150]");
  expectRejected("--fov inf", "--fov");
  expectRejected("--sun-elevation -5", "--sun-elevation must be a number of degrees in [1, 90]");
  expectRejected("--sun-azimuth nan", "--sun-azimuth");
  expectRejected("--camera-position 1,2", "--camera-position must be x,y,z");
  expectRejected("--camera-position 1,nan,3", "--camera-position");
  expectRejected("--camera-look-at 1,2,3,4", "--camera-look-at must be x,y,z");
  expectRejected("--camera-position 0,-3,10 --camera-look-at 0,-3,10", "--camera-look-at");
  expectRejected("--camera-position 0,-3,10 --camera-look-at 0,-9,10", "straight above or below");
  // A camera path checked whole before the first frame: no frame of it is left behind.
  expectRejected("--frames 3 --fps 1 --camera-velocity 0,0,9e6", "camera path leaves 1e7 m",
                 "render", "seq.png");
  EXPECT_FALSE(fs::exists(dir_ / "seq_0000.png"));
}

// --light is checked field by field before any GL work, naming the field.
TEST_F(SampleCli, LightValuesAreChecked) {
  expectRejected("--light lamp:0,-5,0:10", "the type must be point or spot");
  expectRejected("--light point:0,-5:10", "the position must be X,Y,Z");
  expectRejected("--light point:nan,-5,0:10", "the position");
  expectRejected("--light point:0,-5,0:-1", "the intensity must be I or R,G,B");
  expectRejected("--light point:0,-5,0:1,2", "the intensity");
  expectRejected("--light point:0,-5,0:10:-2", "the range must be in [0, 1e6]");
  expectRejected("--light point:0,-5,0", "expected point:X,Y,Z:I[:RANGE]");
  expectRejected("--light spot:0,-5,0:0,0,0:10:40", "the direction must be DX,DY,DZ, not all 0");
  expectRejected("--light spot:0,-5,0:0,-1,0:10:0", "the cone angle must be in (0, 180)");
  expectRejected("--light spot:0,-5,0:0,-1,0:10:180", "the cone angle");
  expectRejected("--light spot:0,-5,0:0,-1,0:10:40:1.5", "the cone softness must be in [0, 1]");
  expectRejected("--light spot:0,-5,0:0,-1,0:10:40:0.2:inf", "the range");
  std::string five;
  for (int i = 0; i < 5; ++i) five += " --light point:0,-5,0:10";
  expectRejected(five, "at most 4 lights");
  std::string four;
  for (int i = 0; i < 4; ++i) four += " --light point:0,-5,0:10";
  expectRejected("--preset torch" + four, "at most 4 in all");
}

TEST_F(SampleCli, RenderWithLightsWritesAnImage) {
  const fs::path out = dir_ / "torch.png";
  const RunResult result = runSample(
      "render --width 64 --height 36 --water-resolution 16 --preset torch --light "
      "point:1,-8,1:20 --light spot:0,-6,3:0,-1,-1:50:30:0:5 --out " +
          out.string(),
      dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_TRUE(result.stderrText.empty()) << result.stderrText;
  EXPECT_TRUE(fs::exists(out));
}

// --exposure scales only what the tone curve sees: the EXR's radiance is the same, its header
// says the exposure, the PNG is brighter; a bad value is refused before any work.
TEST_F(SampleCli, ExposureOnlyChangesTheToneMappedImage) {
  expectRejected("--exposure nan", "--exposure must be a number of stops in [-16, 16]");
  expectRejected("--exposure 17", "--exposure");
  const std::string scene = "render --width 64 --height 36 --water-resolution 16 --out ";
  for (const char* stops : {"0", "2"}) {
    const std::string name = std::string("exposure") + stops;
    for (const char* extension : {".exr", ".png"}) {
      const RunResult result =
          runSample(scene + (dir_ / (name + extension)).string() + " --exposure " + stops, dir_);
      ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    }
  }
  EXPECT_EQ(exrChannel(dir_ / "exposure0.exr", "G"), exrChannel(dir_ / "exposure2.exr", "G"));
  auto header = [](const fs::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    return in ? std::string(in->spec().get_string_attribute("ocean:exposure")) : "(unreadable)";
  };
  EXPECT_EQ(header(dir_ / "exposure0.exr"), "1");
  EXPECT_EQ(header(dir_ / "exposure2.exr"), "4");
  auto meanByte = [](const fs::path& path) {
    auto in = OIIO::ImageInput::open(path.string());
    if (!in) return -1.0;
    std::vector<uint8_t> bytes(size_t(in->spec().image_pixels()) * size_t(in->spec().nchannels));
    if (!in->read_image(0, 0, 0, -1, OIIO::TypeDesc::UINT8, bytes.data())) return -1.0;
    double sum = 0.0;
    for (uint8_t b : bytes) sum += b;
    return sum / double(bytes.size());
  };
  EXPECT_GT(meanByte(dir_ / "exposure2.png"), meanByte(dir_ / "exposure0.png") + 20.0);
}

// Parse errors exit 2 (as before CLI11), failures of the command itself 1; one line each.
TEST_F(SampleCli, ExitCodesAndOneLineErrors) {
  RunResult result = runSample("render --width", dir_);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(result.stderrText, "ocean_sample: option --width needs a value\n");
  result = runSample("compare --width 64", dir_);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.stderrText.find("option --width is not one of compare's"), std::string::npos)
      << result.stderrText;
  result = runSample("report --width 64", dir_);
  EXPECT_EQ(result.exitCode, 2) << "report sizes its own frames; --width would be ignored";
  result = runSample("render stray", dir_);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_NE(result.stderrText.find("unexpected argument 'stray'"), std::string::npos)
      << result.stderrText;
  result = runSample("paint", dir_);
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(result.stderrText, "ocean_sample: unknown command 'paint' (try --help)\n");
  result = runSample("", dir_);
  EXPECT_EQ(result.exitCode, 2);
  result = runSample(
      "render --width 64 --height 36 --preset lagoon --out " + (dir_ / "l.png").string(), dir_);
  EXPECT_EQ(result.exitCode, 1) << "a preset is checked by the command, which fails with 1";
  for (const RunResult& r : {runSample("render --width", dir_), runSample("paint", dir_)}) {
    EXPECT_EQ(std::count(r.stderrText.begin(), r.stderrText.end(), '\n'), 1) << r.stderrText;
  }
}

// --help of each command lists that command's options and no other's; the top-level help
// lists the commands.
TEST_F(SampleCli, HelpPerCommand) {
  RunResult result = runSample("--help", dir_);
  EXPECT_EQ(result.exitCode, 0);
  for (const char* command : {"render", "view", "bench", "report", "reference", "compare"})
    EXPECT_NE(result.stdoutText.find(command), std::string::npos) << command;
  result = runSample("render --help", dir_);
  EXPECT_EQ(result.exitCode, 0);
  for (const char* flag : {"--camera-position", "--camera-look-at", "--fov", "--sun-azimuth",
                           "--sun-elevation", "--frames", "--fps", "--caustics-model"})
    EXPECT_NE(result.stdoutText.find(flag), std::string::npos) << flag;
  EXPECT_EQ(result.stdoutText.find("--plugin"), std::string::npos);
  result = runSample("compare --help", dir_);
  EXPECT_EQ(result.exitCode, 0);
  EXPECT_NE(result.stdoutText.find("--reference"), std::string::npos);
  EXPECT_EQ(result.stdoutText.find("--width"), std::string::npos);
  result = runSample("bench -h", dir_);
  EXPECT_NE(result.stdoutText.find("--json"), std::string::npos);
  EXPECT_NE(result.stdoutText.find("--sun-elevation"), std::string::npos);
  EXPECT_TRUE(result.stderrText.empty()) << result.stderrText;
}

// Bench's JSON is written by nlohmann-json: it parses, and carries the run's size and one
// entry per timed pass with a name and a non-negative median.
TEST_F(SampleCli, BenchJsonParses) {
  const fs::path json = dir_ / "bench.json";
  const RunResult result = runSample(
      "bench --width 32 --height 18 --water-resolution 16 --frames 1 --only none --json " +
          json.string(),
      dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  std::ifstream file(json);
  const nlohmann::json parsed = nlohmann::json::parse(file, nullptr, /*allow_exceptions=*/false);
  ASSERT_FALSE(parsed.is_discarded()) << "not JSON";
  EXPECT_EQ(parsed.value("width", 0), 32);
  EXPECT_EQ(parsed.value("height", 0), 18);
  EXPECT_EQ(parsed.value("preset", ""), "shallow");  // the default
  EXPECT_TRUE(parsed["device"].is_string());
  ASSERT_TRUE(parsed["passes"].is_array());
  bool caustics = false;
  for (const nlohmann::json& pass : parsed["passes"]) {
    ASSERT_TRUE(pass["name"].is_string());
    ASSERT_TRUE(pass["median_ms"].is_number());
    EXPECT_GE(pass["median_ms"].get<double>(), 0.0);
    caustics = caustics || pass["name"] == "caustics";
  }
  EXPECT_TRUE(caustics) << parsed.dump();
}

// The mean frame-to-frame change `render --frames` prints.
double meanFrameChange(const std::string& stdoutText) {
  const std::string key = "frame-to-frame change: mean ";
  const size_t at = stdoutText.find(key);
  return at == std::string::npos ? -1.0 : std::atof(stdoutText.c_str() + at + key.size());
}

constexpr const char* kSequence =
    "render --width 64 --height 36 --water-resolution 16 --frames 3 --time 12.5";

void SampleCli::expectChangeFollowsTheStep(const std::string& arguments) {
  double change[2] = {};
  for (int i = 0; i < 2; ++i) {
    const RunResult result =
        runSample(std::string(kSequence) + " " + arguments + " --fps " + (i ? "480" : "30") +
                      " --out " + (dir_ / (i ? "fast.png" : "slow.png")).string(),
                  dir_);
    ASSERT_EQ(result.exitCode, 0) << result.stderrText;
    change[i] = meanFrameChange(result.stdoutText);
  }
  EXPECT_GT(change[0], 0.0) << arguments;
  EXPECT_LT(change[1], 0.25 * change[0])
      << arguments << ": 30 fps " << change[0] << ", 480 fps " << change[1];
}

// --frames N writes N numbered images and nothing under the plain name.
TEST_F(SampleCli, RenderFramesWritesANumberedSequence) {
  const RunResult result =
      runSample("render --width 48 --height 27 --water-resolution 16 --frames 3 --fps 30 --out " +
                    (dir_ / "seq.exr").string(),
                dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  for (const char* name : {"seq_0000.exr", "seq_0001.exr", "seq_0002.exr"})
    EXPECT_TRUE(fs::exists(dir_ / name)) << name;
  EXPECT_FALSE(fs::exists(dir_ / "seq.exr"));
  EXPECT_FALSE(fs::exists(dir_ / "seq_0003.exr"));
  EXPECT_GT(meanFrameChange(result.stdoutText), 0.0) << "time runs: " << result.stdoutText;
}

// Flicker: the image follows time smoothly, so 16 times shorter steps change each frame far
// less (a smooth signal: about 16 times less; per-frame noise or popping would not shrink).
// 0.25 leaves room for the parts of the pattern that move faster than linearly over a step.
// The camera moves slowly too, as in a game, so a grid that moved with it would show here.
TEST_F(SampleCli, FramesDoNotFlicker) {
  expectChangeFollowsTheStep("--camera-velocity 0.2,0,-0.1");
}

// With time frozen the frame depends on the camera alone: a still camera gives identical
// frames (change exactly 0), and a slowly moving one changes each frame in proportion to its
// step, as above (the god-ray grid and the water lookups are snapped to the world, so a moving
// camera does not make them swim).
TEST_F(SampleCli, FramesWithTimeFrozenChangeOnlyWithTheCamera) {
  const RunResult still =
      runSample(std::string(kSequence) + " --freeze-time --out " + (dir_ / "s.png").string(), dir_);
  ASSERT_EQ(still.exitCode, 0) << still.stderrText;
  EXPECT_EQ(meanFrameChange(still.stdoutText), 0.0) << still.stdoutText;
  expectChangeFollowsTheStep("--freeze-time --camera-velocity 0.2,0,-0.1");
}

// report --only names a section ('stability', the temporal-stability table);
// another name fails before any work, with one line and no report directory.
TEST_F(SampleCli, ReportOnlyUnknownSection) {
  const fs::path out = dir_ / "report_dir";
  const RunResult result = runSample("report --only timing --out " + out.string(), dir_);
  EXPECT_EQ(result.exitCode, 1) << result.stderrText;
  EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1)
      << result.stderrText;
  EXPECT_NE(result.stderrText.find("stability"), std::string::npos) << result.stderrText;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(SampleCli, RenderWritesAReadablePng) {
  const fs::path out = dir_ / "ok.png";
  const RunResult result =
      runSample("render --width 64 --height 36 --water-resolution 16 --out " + out.string(), dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_TRUE(result.stderrText.empty()) << result.stderrText;
  ASSERT_TRUE(fs::exists(out));
  std::ifstream png(out, std::ios::binary);
  std::array<char, 8> magic{};
  png.read(magic.data(), 8);
  EXPECT_EQ(std::string(magic.data() + 1, 3), "PNG");
}

// The traced reference and the compare step: the same contract for bad input.
TEST_F(SampleCli, ReferenceMissingScene) {
  expectRejected("--model " + (dir_ / "missing.glb").string(), "missing.glb", "reference",
                 "ref.exr");
}
TEST_F(SampleCli, ReferenceZeroSize) {
  expectRejected("--width 0", "--width", "reference", "ref.exr");
}
TEST_F(SampleCli, ReferenceNotANumber) {
  expectRejected("--noise nan", "--noise", "reference", "ref.exr");
  expectRejected("--kernel nan", "--kernel", "reference", "ref.exr");
}
TEST_F(SampleCli, ReferenceWritesExrOnly) {
  expectRejected("", ".exr", "reference", "ref.png");
}

// Small EXRs for the compare step (RGB + caustic.lit), all pixels lit.
void writeTestExr(const fs::path& path, int width, int height, float value, bool withNaN) {
  std::vector<float> pixels(size_t(width) * size_t(height) * 5, 1.0f);
  for (size_t i = 0; i < size_t(width) * size_t(height); ++i)
    pixels[5 * i] = value + 0.01f * float(i % 7);
  if (withNaN) pixels[0] = std::nanf("");
  std::string error;
  ASSERT_TRUE(ocean::writeExrChannels(path.string(), width, height,
                                      {"R", "G", "B", "A", "caustic.lit"}, pixels, error))
      << error;
}

TEST_F(SampleCli, CompareMissingInput) {
  writeTestExr(dir_ / "base.exr", 8, 4, 0.5f, false);
  writeTestExr(dir_ / "ref.exr", 8, 4, 1.0f, false);
  expectRejected("--plugin " + (dir_ / "missing.exr").string() + " --reference " +
                     (dir_ / "ref.exr").string() + " --base " + (dir_ / "base.exr").string(),
                 "missing.exr", "compare", "side.png");
}
TEST_F(SampleCli, CompareSizeMismatch) {
  writeTestExr(dir_ / "base.exr", 8, 4, 0.5f, false);
  writeTestExr(dir_ / "ref.exr", 8, 4, 1.0f, false);
  writeTestExr(dir_ / "plugin.exr", 4, 4, 1.0f, false);
  expectRejected("--plugin " + (dir_ / "plugin.exr").string() + " --reference " +
                     (dir_ / "ref.exr").string() + " --base " + (dir_ / "base.exr").string(),
                 "differ in size", "compare", "side.png");
}
TEST_F(SampleCli, CompareNotANumber) {
  writeTestExr(dir_ / "base.exr", 8, 4, 0.5f, false);
  writeTestExr(dir_ / "ref.exr", 8, 4, 1.0f, false);
  writeTestExr(dir_ / "plugin.exr", 8, 4, 1.0f, true);
  expectRejected("--plugin " + (dir_ / "plugin.exr").string() + " --reference " +
                     (dir_ / "ref.exr").string() + " --base " + (dir_ / "base.exr").string(),
                 "NaN", "compare", "side.png");
}

// End to end on a tiny frame: the traced reference of the default preset, then the compare
// step with the reference as its own plugin frame: correlation 1, error 0, a PNG.
TEST_F(SampleCli, ReferenceThenCompareWithItself) {
  const std::string size = " --width 64 --height 36 --water-resolution 16 ";
  const fs::path base = dir_ / "base.exr", ref = dir_ / "ref.exr", side = dir_ / "side.png";
  // The frame without caustics must hold none of the plugin's: compare refuses one with its
  // object caustics, whose light the reference traces instead.
  const fs::path litBase = dir_ / "lit_base.exr";
  ASSERT_EQ(runSample("render --no-caustics" + size + "--out " + litBase.string(), dir_).exitCode,
            0);
  ASSERT_EQ(
      runSample("render --no-caustics --no-object-caustics" + size + "--out " + base.string(), dir_)
          .exitCode,
      0);
  const RunResult traced =
      runSample("reference" + size + "--max-batches 8 --out " + ref.string(), dir_);
  ASSERT_EQ(traced.exitCode, 0) << traced.stderrText;
  EXPECT_NE(traced.stdoutText.find("reference: batch 1,"), std::string::npos) << "progress";
  const RunResult compared =
      runSample("compare --plugin " + ref.string() + " --reference " + ref.string() + " --base " +
                    base.string() + " --out " + side.string(),
                dir_);
  ASSERT_EQ(compared.exitCode, 0) << compared.stderrText;
  EXPECT_NE(compared.stdoutText.find("relative RMSE 0.0000, correlation 1.0000"), std::string::npos)
      << compared.stdoutText;
  // The reference traced the default scene's glass and metal: compare judges their region apart.
  EXPECT_NE(traced.stdoutText.find("casters traced"), std::string::npos) << traced.stdoutText;
  EXPECT_EQ(traced.stdoutText.find("(0 glass/metal casters traced)"), std::string::npos)
      << traced.stdoutText;
  EXPECT_NE(compared.stdoutText.find("compare: object caustics ("), std::string::npos)
      << compared.stdoutText;
  EXPECT_NE(compared.stdoutText.find("correlation 1.0000, relative RMSE 0.0000, flux plugin / "
                                     "reference 1.000"),
            std::string::npos)
      << compared.stdoutText;
  EXPECT_TRUE(fs::exists(side));
  const RunResult mismatched =
      runSample("compare --plugin " + ref.string() + " --reference " + ref.string() + " --base " +
                    litBase.string() + " --out " + side.string(),
                dir_);
  EXPECT_EQ(mismatched.exitCode, 1) << mismatched.stdoutText;
  EXPECT_NE(mismatched.stderrText.find("has the plugin's object caustics in it: render it with "
                                       "--no-caustics --no-object-caustics"),
            std::string::npos)
      << mismatched.stderrText;
  // With flat water's frame: the pattern alone, a third row in the side by side.
  const fs::path flat = dir_ / "flat.exr", patternSide = dir_ / "pattern.png";
  ASSERT_EQ(runSample("render --caustics-model ray-deviation --tau 0 --no-object-caustics" + size +
                          "--out " + flat.string(),
                      dir_)
                .exitCode,
            0);
  const RunResult pattern =
      runSample("compare --plugin " + ref.string() + " --reference " + ref.string() + " --base " +
                    base.string() + " --flat " + flat.string() + " --out " + patternSide.string(),
                dir_);
  ASSERT_EQ(pattern.exitCode, 0) << pattern.stderrText;
  EXPECT_NE(pattern.stdoutText.find("correlation 1.0000, relative RMSE 0.0000"), std::string::npos)
      << pattern.stdoutText;
  // 64x36 holds no 32x32 patch of compared pixels: the spectrum says so rather than guess.
  EXPECT_NE(pattern.stdoutText.find("sharpness: no patch"), std::string::npos)
      << pattern.stdoutText;
  int sideWidth = 0, sideHeight = 0, patternWidth = 0, patternHeight = 0;
  ASSERT_TRUE(imageSize(side, sideWidth, sideHeight));
  ASSERT_TRUE(imageSize(patternSide, patternWidth, patternHeight));
  EXPECT_EQ(patternWidth, sideWidth);
  EXPECT_GT(patternHeight, sideHeight) << "a third row";
}

// The reference traces the glass itself. A glass sphere of IOR 1.0 under water
// (an air bubble: it spreads its light and reflects its rim) and one of 1.5 (it focuses) once
// gave the same reference; now the traced light through them differs as the optics say.
TEST_F(SampleCli, ReferenceTracesTheGlassOfAModel) {
  std::vector<float> light[2];
  const float iors[2] = {1.0f, 1.5f};
  for (int k = 0; k < 2; ++k) {
    ocean_scene::Model sphere;
    std::string error;
    ASSERT_TRUE(
        ocean_scene::loadGlb(std::string(OCEAN_ASSETS) + "/glass_sphere.glb", sphere, error))
        << error;
    ASSERT_FALSE(sphere.materials.empty());
    for (ocean_scene::Material& m : sphere.materials) m.ior = iors[k];
    const fs::path model = dir_ / ("sphere" + std::to_string(k) + ".glb");
    ASSERT_TRUE(ocean_scene::writeGlb(sphere, model.string(), error)) << error;
    const fs::path out = dir_ / ("ref" + std::to_string(k) + ".exr");
    // Near the seabed camera, 1 m across, 0.8 m over the sand: its shadow is in view.
    const RunResult traced = runSample(
        "reference --preset seabed --width 96 --height 54 --water-resolution 16 "
        "--max-batches 4 --model " +
            model.string() + "@3.5,0.8,9.5:fit=1 --out " + out.string(),
        dir_);
    ASSERT_EQ(traced.exitCode, 0) << traced.stderrText;
    light[k] = exrChannel(out, "caustic.objectE");
    ASSERT_EQ(light[k].size(), size_t(96 * 54));
  }
  // Where the model's light falls (the rest of the scene is the same in both): the dense sphere
  // focuses above flat water's light, the bubble stays below it and delivers less in all.
  double peak[2] = {0.0, 0.0}, sum[2] = {0.0, 0.0};
  size_t changed = 0;
  for (size_t i = 0; i < light[0].size(); ++i) {
    if (!(std::abs(light[1][i] - light[0][i]) > 0.02f)) continue;
    ++changed;
    for (int k = 0; k < 2; ++k) {
      peak[k] = std::max(peak[k], double(light[k][i]));
      sum[k] += double(light[k][i]);
    }
  }
  std::printf("%zu pixels differ: IOR 1.0 peak %.3f sum %.2f, IOR 1.5 peak %.3f sum %.2f\n",
              changed, peak[0], sum[0], peak[1], sum[1]);
  EXPECT_GT(changed, 20u);
  EXPECT_GT(peak[1], 1.5);
  EXPECT_LT(peak[0], 1.0);
  EXPECT_GT(sum[1], 1.5 * sum[0]);
}

// A local light's object caustics are traced too. The night dive (the sun
// below the horizon, a torch shining through the glass sphere) has nothing else to compare; the
// plugin's caustic under the sphere agrees with the traced one.
TEST_F(SampleCli, ReferenceTracesATorchThroughTheGlass) {
  const std::string scene = " --preset torch --width 96 --height 54 --water-resolution 16 ";
  const fs::path plugin = dir_ / "p.exr", base = dir_ / "b.exr", ref = dir_ / "r.exr";
  ASSERT_EQ(runSample("render" + scene + "--out " + plugin.string(), dir_).exitCode, 0);
  ASSERT_EQ(
      runSample("render --no-caustics --no-object-caustics" + scene + "--out " + base.string(),
                dir_)
          .exitCode,
      0);
  const RunResult traced = runSample("reference" + scene + "--out " + ref.string(), dir_);
  ASSERT_EQ(traced.exitCode, 0) << traced.stderrText;
  EXPECT_NE(traced.stdoutText.find("1 local light(s) traced through the casters"),
            std::string::npos)
      << traced.stdoutText;
  const RunResult compared =
      runSample("compare --plugin " + plugin.string() + " --reference " + ref.string() +
                    " --base " + base.string() + " --out " + (dir_ / "side.png").string(),
                dir_);
  ASSERT_EQ(compared.exitCode, 0) << compared.stderrText;
  EXPECT_NE(compared.stdoutText.find("no sunlit underwater pixel"), std::string::npos);
  const size_t at = compared.stdoutText.find("falls): correlation ");
  ASSERT_NE(at, std::string::npos) << compared.stdoutText;
  double correlation = 0.0, rmse = 0.0, flux = 0.0;
  ASSERT_EQ(std::sscanf(compared.stdoutText.c_str() + at,
                        "falls): correlation %lf, relative RMSE %lf, flux plugin / reference %lf",
                        &correlation, &rmse, &flux),
            3)
      << compared.stdoutText;
  EXPECT_GT(correlation, 0.8);
  EXPECT_GT(flux, 0.8);
  EXPECT_LT(flux, 1.25);
}

// Motion a browser shows. --frames N with a .gif output writes one looping
// animation of N frames at the stated rate (GIF's whole hundredths of a second), and the
// caustics move between its frames.
TEST_F(SampleCli, RenderWritesAnAnimatedGif) {
  const fs::path out = dir_ / "loop.gif";
  const RunResult result =
      runSample("render --width 64 --height 36 --water-resolution 16 --frames 3 --fps 20 --out " +
                    out.string(),
                dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  EXPECT_NE(result.stdoutText.find("3 frames at 20 fps"), std::string::npos) << result.stdoutText;
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  int subimages = 0;
  std::vector<std::vector<uint8_t>> frames;
  while (in->seek_subimage(subimages, 0)) {
    const OIIO::ImageSpec& spec = in->spec();
    EXPECT_EQ(spec.width, 64);
    EXPECT_EQ(spec.height, 36);
    const OIIO::ParamValue* rate = spec.find_attribute("FramesPerSecond", OIIO::TypeRational);
    ASSERT_NE(rate, nullptr);
    const int* r = static_cast<const int*>(rate->data());
    EXPECT_DOUBLE_EQ(double(r[0]) / double(r[1]), 20.0);
    std::vector<uint8_t> pixels(size_t(spec.width) * size_t(spec.height) * size_t(spec.nchannels));
    ASSERT_TRUE(
        in->read_image(subimages, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, pixels.data()));
    frames.push_back(std::move(pixels));
    ++subimages;
  }
  EXPECT_EQ(subimages, 3);
  ASSERT_EQ(frames.size(), 3u);
  EXPECT_NE(frames.front(), frames.back()) << "time runs: the light moves";
  // A rate GIF cannot store exactly is rounded to whole hundredths of a second, and said so.
  const RunResult thirty =
      runSample("render --width 64 --height 36 --water-resolution 16 --frames 2 --fps 30 --out " +
                    (dir_ / "thirty.gif").string(),
                dir_);
  ASSERT_EQ(thirty.exitCode, 0) << thirty.stderrText;
  EXPECT_NE(thirty.stdoutText.find("2 frames at 33.3333 fps"), std::string::npos)
      << thirty.stdoutText;
  // Too large to hold: refused before any frame, nothing written.
  const RunResult big = runSample(
      "render --width 4096 --height 4096 --frames 40 --out " + (dir_ / "big.gif").string(), dir_);
  EXPECT_EQ(big.exitCode, 1);
  EXPECT_NE(big.stderrText.find("MiB in memory, over 2048"), std::string::npos) << big.stderrText;
  EXPECT_FALSE(fs::exists(dir_ / "big.gif"));
}

// view's own flags are refused before a window would open: no display is needed for that.
TEST_F(SampleCli, ViewScreenshotRefusedWithoutAWindow) {
  unsetenv("DISPLAY");
  unsetenv("WAYLAND_DISPLAY");
  const std::string size = "view --width 64 --height 36 --water-resolution 16 ";
  const struct {
    std::string arguments, mentions;
    int exitCode;
  } cases[] = {
      {"--frames 1 --screenshot " + (dir_ / "shot.jpg").string(), "--screenshot", 2},
      {"--frames 1 --screenshot " + (dir_ / "missing" / "shot.png").string(), "missing", 1},
      {"--frames 0", "--frames", 2},
  };
  for (const auto& c : cases) {
    const RunResult result = runSample(size + c.arguments, dir_);
    EXPECT_EQ(result.exitCode, c.exitCode) << c.arguments << ": " << result.stderrText;
    EXPECT_EQ(std::count(result.stderrText.begin(), result.stderrText.end(), '\n'), 1)
        << result.stderrText;
    EXPECT_NE(result.stderrText.find(c.mentions), std::string::npos) << result.stderrText;
  }
  EXPECT_TRUE(fs::is_empty(dir_)) << "a refused view left a file";
}

}  // namespace

// render --views 2: one image, the two views side by side, each half drawn with light; the left
// half is the same frame as a one-view render of that size (the split changes nothing in it).
TEST_F(SampleCli, SplitScreenViewsRenderSideBySide) {
  const fs::path split = dir_ / "split.exr", single = dir_ / "single.exr";
  const RunResult two = runSample(
      "render --width 64 --height 36 --water-resolution 16 --views 2 "
      "--out " +
          split.string(),
      dir_);
  ASSERT_EQ(two.exitCode, 0) << two.stderrText;
  const RunResult one = runSample(
      "render --width 32 --height 36 --water-resolution 16 --out " + single.string(), dir_);
  ASSERT_EQ(one.exitCode, 0) << one.stderrText;
  auto in = OIIO::ImageInput::open(split.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 64);
  EXPECT_EQ(in->spec().height, 36);
  in.reset();
  const std::vector<float> both = exrChannel(split, "R"), left = exrChannel(single, "R");
  ASSERT_EQ(both.size(), 64u * 36u);
  ASSERT_EQ(left.size(), 32u * 36u);
  double rightSum = 0.0;
  int differing = 0;
  for (int y = 0; y < 36; ++y)
    for (int x = 0; x < 32; ++x) {
      differing += both[size_t(y * 64 + x)] != left[size_t(y * 32 + x)];
      rightSum += double(both[size_t(y * 64 + 32 + x)]);
    }
  EXPECT_EQ(differing, 0) << "the left view differs from a one-view render";
  EXPECT_GT(rightSum, 0.0) << "the right view is black";
}

// render --cube-map: six faces of --width / 4 as a 4 x 3 cross, the empty cells 0.
TEST_F(SampleCli, CubeMapProbeIsACrossOfSixFaces) {
  const fs::path out = dir_ / "probe.exr";
  const RunResult result =
      runSample("render --width 64 --water-resolution 16 --cube-map --out " + out.string(), dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  auto in = OIIO::ImageInput::open(out.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 64);
  EXPECT_EQ(in->spec().height, 48);
  in.reset();
  const std::vector<float> red = exrChannel(out, "R");
  ASSERT_EQ(red.size(), 64u * 48u);
  // Cells of 16 x 16, rows from the top of the file: +Y at (1, 0); -X -Z +X +Z on row 1; -Y at
  // (1, 2). Each face has light, each empty cell none.
  auto cellSum = [&](int cx, int cy) {
    double sum = 0.0;
    for (int y = 0; y < 16; ++y)
      for (int x = 0; x < 16; ++x) sum += double(red[size_t((cy * 16 + y) * 64 + cx * 16 + x)]);
    return sum;
  };
  for (auto [cx, cy] : {std::pair{1, 0}, {0, 1}, {1, 1}, {2, 1}, {3, 1}, {1, 2}})
    EXPECT_GT(cellSum(cx, cy), 0.0) << "face at cell " << cx << ", " << cy << " is black";
  for (auto [cx, cy] : {std::pair{0, 0}, {2, 0}, {3, 0}, {0, 2}, {2, 2}, {3, 2}})
    EXPECT_EQ(cellSum(cx, cy), 0.0) << "empty cell " << cx << ", " << cy << " has light";
}

// The cross's size follows from --width alone: an explicit --height was ignored, and a width 4
// does not divide made a cross of another width (--width 3: a 4x3 image, exit 0).
TEST_F(SampleCli, CubeMapRefusesAHeightAndAWidthFourDoesNotDivide) {
  expectRejected("--cube-map", "render --cube-map takes no --height (got 36)");
  const fs::path out = dir_ / "cube3.png";
  const RunResult result =
      runSample("render --width 3 --water-resolution 16 --cube-map --out " + out.string(), dir_);
  EXPECT_NE(result.exitCode, 0);
  EXPECT_NE(result.stderrText.find("render --cube-map needs a --width that 4 divides"),
            std::string::npos)
      << result.stderrText;
  EXPECT_FALSE(fs::exists(out));
  const RunResult help = runSample("render --help", dir_);
  EXPECT_NE(help.stdoutText.find("--height is not taken"), std::string::npos) << help.stdoutText;
}

// render --model without a position puts the model where the default preset looks: the image
// changes (the row stood at z = 5, outside the shallow preset's view, and changed nothing).
TEST_F(SampleCli, AModelChangesTheDefaultPresetsImage) {
  const std::string base = "render --width 64 --height 36 --water-resolution 16 --out ";
  const fs::path plain = dir_ / "plain.exr", with = dir_ / "with_model.exr";
  ASSERT_EQ(runSample(base + plain.string(), dir_).exitCode, 0);
  const RunResult result = runSample(
      base + with.string() + " --model " + std::string(OCEAN_ASSETS) + "/glass_sphere.glb", dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  const std::vector<float> a = exrChannel(plain, "R"), b = exrChannel(with, "R");
  ASSERT_EQ(a.size(), b.size());
  ASSERT_FALSE(a.empty());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.size(); ++i) differing += std::abs(a[i] - b[i]) > 1e-3f ? 1 : 0;
  EXPECT_GT(differing, a.size() / 100) << "the model is out of the default preset's view";
}

TEST_F(SampleCli, ViewsOutOfRangeOrNotDividingTheWidth) {
  expectRejected("--views 5", "--views");
  expectRejected("--views 0", "--views");
  expectRejected("--views 3", "divides");  // 64 is not a multiple of 3
  expectRejected("--views 2", "not an animation", "render", "out.gif");
  expectRejected("--cube-map", "--cube-map", "bench");
  expectRejected("--stereo --cube-map", "one of");
  expectRejected("--stereo --views 2", "one of");
}

// render --stereo: two eyes 6.4 cm apart side by side; the halves are almost the same picture
// (a few pixels of parallax apart, so compared in 8 x 8 blocks), not the same one, and both
// have the same light. (At 64 x 36 an eye, aliasing alone moves the mean by 10 %: too small.)
TEST_F(SampleCli, StereoPairIsTwoNearlyEqualEyes) {
  const fs::path out = dir_ / "stereo.exr";
  const RunResult result = runSample(
      "render --width 320 --height 90 --water-resolution 16 --stereo --out " + out.string(), dir_);
  ASSERT_EQ(result.exitCode, 0) << result.stderrText;
  // Green: under water the light is mostly green (red is absorbed within metres).
  const std::vector<float> green = exrChannel(out, "G");
  ASSERT_EQ(green.size(), 320u * 90u);
  double sl = 0, sr = 0, sll = 0, srr = 0, slr = 0;
  int differing = 0, n = 0;
  for (int by = 0; by < 11; ++by)
    for (int bx = 0; bx < 20; ++bx) {
      double l = 0.0, r = 0.0;
      for (int y = by * 8; y < by * 8 + 8; ++y)
        for (int x = bx * 8; x < bx * 8 + 8; ++x) {
          const float left = green[size_t(y * 320 + x)], right = green[size_t(y * 320 + 160 + x)];
          l += double(left);
          r += double(right);
          differing += left != right;
        }
      sl += l, sr += r, sll += l * l, srr += r * r, slr += l * r, ++n;
    }
  const double correlation = (slr / n - sl / n * sr / n) /
                             std::sqrt((sll / n - sl / n * sl / n) * (srr / n - sr / n * sr / n));
  EXPECT_GT(sl, 0.0);
  EXPECT_NEAR(sr / sl, 1.0, 0.02) << "the eyes see different light";
  EXPECT_GT(correlation, 0.95) << "the eyes do not see one scene";
  EXPECT_GT(differing, 0) << "the eyes are the same camera";
  std::printf("stereo eyes: 8x8-block correlation %.4f, right/left light %.4f\n", correlation,
              sr / sl);
}
