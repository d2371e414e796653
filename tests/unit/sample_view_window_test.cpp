// `ocean_sample view` in a real window, on an X server of its own (Xvfb): a few counted frames,
// a screenshot of the window through OpenImageIO, and the 3D view compared with a headless
// `ocean_sample render` of the same frame. Skipped, with the reason, where Xvfb is missing or
// cannot start a display: a machine without X is not a failure of the view.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/inotify.h>
#include <sys/wait.h>
#include <unistd.h>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

// The frame both paths draw: small, a cheap ocean, time held (--freeze-time) so that the
// view's third frame is render's only one.
const std::vector<std::string> kFrame = {"--preset",           "seabed", "--width", "480",
                                         "--height",           "270",    "--time",  "12.5",
                                         "--water-resolution", "64"};

// Well above the few seconds llvmpipe needs for a frame this size, even on a loaded machine;
// a view that does not quit after its frames is killed and fails the test.
constexpr int kViewTimeoutSeconds = 240;

bool onPath(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::stringstream entries(path != nullptr ? path : "");
  std::string directory;
  while (std::getline(entries, directory, ':')) {
    if (!directory.empty() && access((fs::path(directory) / program).c_str(), X_OK) == 0)
      return true;
  }
  return false;
}

struct Exit {
  bool timedOut = false;
  int code = -1;  // -1: killed by a signal
};

// Runs `argv` in `directory` with DISPLAY set (empty: unset), stdout and stderr to `log`;
// SIGKILL after `timeoutSeconds`.
Exit run(const std::vector<std::string>& argv, const fs::path& directory,
         const std::string& display, const fs::path& log, int timeoutSeconds) {
  const pid_t child = fork();
  if (child == 0) {
    if (chdir(directory.c_str()) != 0) _exit(127);
    if (display.empty())
      unsetenv("DISPLAY");
    else
      setenv("DISPLAY", display.c_str(), 1);
    const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0) _exit(127);
    dup2(out, 1);
    dup2(out, 2);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  Exit result;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  int status = 0;
  while (waitpid(child, &status, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      result.timedOut = true;
      return result;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  result.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// An X server on a display number it picks itself (-displayfd), so parallel tests and other
// servers on this machine never collide.
class Xvfb {
 public:
  // Empty when it could not start; `why` says what happened.
  std::string start(std::string& why) {
    int fds[2];
    if (pipe(fds) != 0) {
      why = "no pipe";
      return "";
    }
    pid_ = fork();
    if (pid_ == 0) {
      close(fds[0]);
      const int null = open("/dev/null", O_WRONLY);
      dup2(null, 1);
      dup2(null, 2);
      const std::string fd = std::to_string(fds[1]);
      execlp("Xvfb", "Xvfb", "-displayfd", fd.c_str(), "-screen", "0", "640x480x24", "-nolisten",
             "tcp", static_cast<char*>(nullptr));
      _exit(127);
    }
    close(fds[1]);
    std::string number;
    pollfd readable{fds[0], POLLIN, 0};
    // The display number arrives once the server accepts clients, normally within a second.
    while (poll(&readable, 1, 20000) > 0) {
      char c = 0;
      if (read(fds[0], &c, 1) != 1 || c == '\n') break;
      number += c;
    }
    close(fds[0]);
    if (number.empty()) {
      why = "Xvfb exited or reported no display within 20 s";
      stop();
      return "";
    }
    return ":" + number;
  }
  void stop() {
    if (pid_ <= 0) return;
    kill(pid_, SIGTERM);
    waitpid(pid_, nullptr, 0);
    pid_ = -1;
  }
  ~Xvfb() { stop(); }

 private:
  pid_t pid_ = -1;
};

struct Image {
  int width = 0, height = 0, channels = 0;
  std::vector<unsigned char> pixels;
};

Image load(const fs::path& path) {
  Image image;
  auto input = OIIO::ImageInput::open(path.string());
  if (!input) return image;
  const OIIO::ImageSpec& spec = input->spec();
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.pixels.resize(size_t(spec.width) * spec.height * spec.nchannels);
  if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::UINT8, image.pixels.data()))
    image.pixels.clear();
  return image;
}

// RGB differences over the columns [x0, x1) (alpha is left out: a window's visual need not
// store it, and it is not part of what the user sees).
struct Difference {
  int maxChannel = 0;
  size_t pixels = 0;  // pixels with any RGB channel different
};

Difference compareRgb(const Image& a, const Image& b, int x0, int x1) {
  Difference d;
  for (int y = 0; y < a.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      bool differs = false;
      for (int c = 0; c < 3; ++c) {
        const int va = a.pixels[(size_t(y) * a.width + x) * a.channels + c];
        const int vb = b.pixels[(size_t(y) * b.width + x) * b.channels + c];
        d.maxChannel = std::max(d.maxChannel, std::abs(va - vb));
        differs |= va != vb;
      }
      d.pixels += differs ? 1 : 0;
    }
  }
  return d;
}

class SampleViewWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!onPath("Xvfb")) GTEST_SKIP() << "Xvfb is not installed (Debian package xvfb)";
    std::string why;
    display_ = xvfb_.start(why);
    if (display_.empty()) GTEST_SKIP() << "no X server could start: " << why;
    const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("ocean_view_" + std::to_string(::getpid()) + "_" + test->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "run");
    // Dear ImGui reads its layout from imgui.ini in the working directory unless told not to:
    // one is planted there, and the view must not open it (watched below).
    std::ofstream(dir_ / "run" / "imgui.ini") << "[Window][postfx (H hides)]\nPos=300,300\n";
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }

  // The view's screenshot after three counted frames; fails the test (and returns an empty
  // image) when the view fails, hangs, opens the planted imgui.ini or leaves other files.
  Image view(const std::vector<std::string>& extra) {
    const int watch = inotify_init1(IN_NONBLOCK);
    EXPECT_GE(watch, 0);
    inotify_add_watch(watch, (dir_ / "run" / "imgui.ini").c_str(), IN_OPEN | IN_ACCESS);
    std::vector<std::string> argv = {OCEAN_SAMPLE_EXE, "view"};
    argv.insert(argv.end(), kFrame.begin(), kFrame.end());
    for (const char* a : {"--freeze-time", "--frames", "3", "--screenshot", "shot.png"})
      argv.emplace_back(a);
    argv.insert(argv.end(), extra.begin(), extra.end());
    const fs::path log = dir_ / "view.log";
    const Exit exit = run(argv, dir_ / "run", display_, log, kViewTimeoutSeconds);
    char events[4096];
    const ssize_t opened = read(watch, events, sizeof(events));
    close(watch);
    EXPECT_FALSE(exit.timedOut) << "view still running after " << kViewTimeoutSeconds << " s";
    EXPECT_EQ(exit.code, 0) << readText(log);
    EXPECT_LE(opened, 0) << "the view opened imgui.ini, a file it was not given";
    for (const auto& entry : fs::directory_iterator(dir_ / "run")) {
      const std::string name = entry.path().filename().string();
      EXPECT_TRUE(name == "shot.png" || name == "imgui.ini") << "the view left " << name;
    }
    return load(dir_ / "run" / "shot.png");
  }

  Image render() {
    std::vector<std::string> argv = {OCEAN_SAMPLE_EXE, "render"};
    argv.insert(argv.end(), kFrame.begin(), kFrame.end());
    argv.emplace_back("--out");
    argv.emplace_back((dir_ / "render.png").string());
    const fs::path log = dir_ / "render.log";
    const Exit exit = run(argv, dir_, "", log, kViewTimeoutSeconds);
    EXPECT_FALSE(exit.timedOut);
    EXPECT_EQ(exit.code, 0) << readText(log);
    return load(dir_ / "render.png");
  }

  Xvfb xvfb_;
  std::string display_;
  fs::path dir_;
};

// The window path (GLFW's GLX context on Xvfb, Mesa llvmpipe as the headless EGL path uses, the
// tone-mapped image blitted 1:1 into the window) must show what render writes. Both run the
// same shaders on the same rasteriser with the same inputs, so the expected difference is none;
// the tolerance allows one 8-bit step on 0.1 % of the pixels, for a Mesa that rounds a
// blit or a GLX visual's conversion differently, and nothing more: a wrong clock, camera,
// setting or a missed frame moves far more pixels than that (the water alone moves every
// underwater pixel between frames).
TEST_F(SampleViewWindow, ThreeDViewMatchesHeadlessRender) {
  const Image shown = view({"--no-overlay"});
  const Image rendered = render();
  ASSERT_FALSE(shown.pixels.empty());
  ASSERT_FALSE(rendered.pixels.empty());
  ASSERT_EQ(shown.width, rendered.width);
  ASSERT_EQ(shown.height, rendered.height);
  const Difference d = compareRgb(shown, rendered, 0, shown.width);
  std::printf("window vs headless: %zu of %d pixels differ, largest channel difference %d\n",
              d.pixels, shown.width * shown.height, d.maxChannel);
  EXPECT_LE(d.maxChannel, 1);
  EXPECT_LE(double(d.pixels), 0.001 * shown.width * shown.height);
}

// The overlay draws over the left of the frame (its window is 400 px wide at x = 8) and
// leaves the rest as render wrote it.
TEST_F(SampleViewWindow, OverlayDrawsOverTheFrameOnly) {
  const Image shown = view({});
  const Image rendered = render();
  ASSERT_FALSE(shown.pixels.empty());
  ASSERT_FALSE(rendered.pixels.empty());
  ASSERT_EQ(shown.width, rendered.width);
  const Difference covered = compareRgb(shown, rendered, 0, 400);
  EXPECT_GT(double(covered.pixels), 0.3 * 400 * shown.height) << "no overlay drawn";
  const Difference beside = compareRgb(shown, rendered, 420, shown.width);
  EXPECT_LE(beside.maxChannel, 1);
  EXPECT_LE(double(beside.pixels), 0.001 * (shown.width - 420) * shown.height);
}

}  // namespace
