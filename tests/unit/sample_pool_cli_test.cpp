// `ocean_sample render --preset pool`: the pool renders headless, its water moves from frame to
// frame, the same command gives the same frames bit for bit (scripted drops, the ball, the
// simulation's whole steps), and a --model it cannot place is refused with one line. The wake
// preset renders and moves too.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

namespace {

namespace fs = std::filesystem;

struct SampleRun {
  int exitCode = -1;
  std::string err, out;
};

std::string slurp(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

SampleRun runSample(const std::string& arguments, const fs::path& scratch) {
  const fs::path err = scratch / "stderr.txt", out = scratch / "stdout.txt";
  const std::string command =
      std::string(OCEAN_SAMPLE_EXE) + " " + arguments + " 2>" + err.string() + " >" + out.string();
  const int status = std::system(command.c_str());
  SampleRun run;
  run.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = slurp(err);
  run.out = slurp(out);
  return run;
}

// RGB of an EXR as floats, empty when it cannot be read.
std::vector<float> readRgb(const fs::path& path, int& width, int& height) {
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) return {};
  width = in->spec().width;
  height = in->spec().height;
  std::vector<float> rgb(size_t(width) * size_t(height) * 3);
  if (!in->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, rgb.data())) return {};
  return rgb;
}

class PoolCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    scratch_ = fs::temp_directory_path() /
               ("ocean_pool_cli_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
  }
  void TearDown() override { fs::remove_all(scratch_); }

  // Three frames at 160x90 into scratch/<name>_000N.exr; the frames' RGB.
  std::vector<std::vector<float>> renderFrames(const std::string& name) {
    const fs::path out = scratch_ / (name + ".exr");
    const SampleRun run = runSample(
        "render --preset pool --width 160 --height 90 --frames 3 --out " + out.string(), scratch_);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    std::vector<std::vector<float>> frames;
    for (int i = 0; i < 3; ++i) {
      const fs::path frame = scratch_ / (name + "_000" + std::to_string(i) + ".exr");
      int width = 0, height = 0;
      frames.push_back(readRgb(frame, width, height));
      EXPECT_EQ(width, 160) << frame;
      EXPECT_EQ(height, 90) << frame;
    }
    return frames;
  }

  fs::path scratch_;
};

double meanAbs(const std::vector<float>& a) {
  double sum = 0.0;
  for (float v : a) sum += std::abs(double(v));
  return a.empty() ? 0.0 : sum / double(a.size());
}

TEST_F(PoolCli, RendersHeadlessAndTheWaterMoves) {
  const auto frames = renderFrames("pool");
  ASSERT_EQ(frames.size(), 3u);
  for (const auto& frame : frames) {
    ASSERT_EQ(frame.size(), size_t(160 * 90 * 3));
    for (float v : frame) ASSERT_TRUE(std::isfinite(v) && v >= 0.0f);
    EXPECT_GT(meanAbs(frame), 0.01);  // lit: the deck, the pool, the ball
  }
  // 1/30 s apart: the ripples, their light on the floor and the ball have moved. The deck
  // (half the frame) does not: the whole frame changes by ~4.5 % (render prints 0.044, 0.050).
  for (int i = 1; i < 3; ++i) {
    double change = 0.0;
    for (size_t k = 0; k < frames[0].size(); ++k)
      change += std::abs(double(frames[size_t(i)][k]) - double(frames[size_t(i - 1)][k]));
    change /= double(frames[0].size());
    EXPECT_GT(change / meanAbs(frames[0]), 0.01) << "frame " << i;
  }
}

// The drops fall at fixed times on hashed places, the ball follows its path and the simulation
// runs whole steps from a rest 4 s before the first frame: two runs are the same bit for bit.
TEST_F(PoolCli, SameCommandSameFrames) {
  const auto first = renderFrames("a");
  const auto second = renderFrames("b");
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) {
    ASSERT_FALSE(first[i].empty());
    EXPECT_TRUE(first[i] == second[i]) << "frame " << i << " differs between two runs";
  }
}

// The wake preset renders finite frames that change (1.4 % a frame at 160x90: the sea, the ball
// and its wake all move; this does not tell them apart).
TEST_F(PoolCli, WakeRendersAndMoves) {
  const fs::path out = scratch_ / "wake.exr";
  const SampleRun run = runSample(
      "render --preset wake --width 160 --height 90 --frames 2 --out " + out.string(), scratch_);
  ASSERT_EQ(run.exitCode, 0) << run.err;
  int width = 0, height = 0;
  const std::vector<float> a = readRgb(scratch_ / "wake_0000.exr", width, height);
  const std::vector<float> b = readRgb(scratch_ / "wake_0001.exr", width, height);
  ASSERT_EQ(a.size(), size_t(160 * 90 * 3));
  ASSERT_EQ(b.size(), a.size());
  double change = 0.0;
  for (size_t k = 0; k < a.size(); ++k) {
    ASSERT_TRUE(std::isfinite(a[k]) && std::isfinite(b[k]));
    change += std::abs(double(b[k]) - double(a[k]));
  }
  EXPECT_GT(change / double(a.size()) / meanAbs(a), 0.005);
}

TEST_F(PoolCli, RefusesModelsItCannotPlace) {
  const fs::path out = scratch_ / "x.png";
  const SampleRun run = runSample("render --preset pool --width 64 --height 36 --model " +
                                      (scratch_ / "none.glb").string() + " --out " + out.string(),
                                  scratch_);
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.err.find("pool"), std::string::npos) << run.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
