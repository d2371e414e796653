// ocean_sample render: one headless frame to an image, or with --frames N an image sequence
// (or one animated GIF, when --out ends in .gif) with time running (and the camera on its slow
// path), each frame's change from the one before on stdout.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <glcontext/context.h>

#include "camera.h"
#include "commands.h"
#include "frame_sequence.h"
#include "headless_session.h"
#include "image_output.h"
#include "plugin_setup.h"
#include "renderer.h"

namespace ocean {
namespace {

// Renders the frame and fails on any GL error the driver logged.
bool renderChecked(HeadlessSession& session, const FrameInput& input, std::string& error) {
  if (!session.renderer->render(input, error)) return false;
  for (const auto& message : session.context->debugLog().take()) {
    if (message.type == GL_DEBUG_TYPE_ERROR) {
      error = glcontext::debugMessageString(message);
      return false;
    }
  }
  return true;
}

}  // namespace

int runRender(const Options& options) {
  if (options.views > 1 || options.cubeMap || options.stereo) return runRenderViews(options);
  std::string error;
  std::string extension = std::filesystem::path(options.out).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  const bool animation = extension == ".gif";
  const bool sequence = options.frames > 1 && !animation;
  // Checked before any work so a bad path fails fast and leaves nothing behind (every frame of
  // a sequence goes to the same directory with the same extension).
  const std::string firstName =
      sequence ? sequenceFrameName(options.out, 0, options.frames) : options.out;
  if (!checkOutputPath(firstName, error)) return commandFailed(error);
  // An animation is held in memory until it is written whole.
  constexpr double kMaxAnimationBytes = 2.0 * 1024 * 1024 * 1024;
  const double animationBytes =
      4.0 * double(options.width) * double(options.height) * double(options.frames);
  if (animation && animationBytes > kMaxAnimationBytes)
    return commandFailed("an animated GIF of " + std::to_string(options.frames) + " frames of " +
                         std::to_string(options.width) + "x" + std::to_string(options.height) +
                         " needs " + std::to_string(std::llround(animationBytes / 1048576.0)) +
                         " MiB in memory, over 2048: fewer --frames or a smaller size");
  std::vector<std::vector<uint8_t>> animationFrames;
  HeadlessSession session;
  if (!openHeadlessSession(options, /*debug=*/true, /*benchmarkFloor=*/false, session, error)) {
    return commandFailed(error);
  }
  // The whole camera path is checked before the first frame is written.
  std::vector<Camera> cameras(size_t(options.frames));
  for (int frame = 0; frame < options.frames; ++frame) {
    if (!cameraAt(options, session.preset.camera, frame / options.fps, cameras[size_t(frame)]))
      return commandFailed(
          "the camera path leaves 1e7 m from the origin or passes straight above or below "
          "--camera-look-at at " +
          std::to_string(frame / options.fps) + " s");
  }
  Renderer& renderer = *session.renderer;
  std::vector<float> previous;
  double changeSum = 0.0, changeMax = 0.0;
  for (int frame = 0; frame < options.frames; ++frame) {
    const double seconds = frame / options.fps;
    const FrameInput input{cameras[size_t(frame)], session.preset.sun,
                           options.timeSeconds + (options.freezeTime ? 0.0 : seconds)};
    if (!renderChecked(session, input, error)) return commandFailed(error);
    std::vector<float> radiance = renderer.readRadiance();
    if (animation) {
      animationFrames.push_back(renderer.readColor());
      if (!previous.empty()) {
        const double change = relativeFrameChange(previous, radiance);
        changeSum += change;
        changeMax = std::max(changeMax, change);
      }
      std::printf("frame %d of %d\n", frame + 1, options.frames);
      std::fflush(stdout);
      previous = std::move(radiance);
      continue;
    }
    const std::string name =
        sequence ? sequenceFrameName(options.out, frame, options.frames) : options.out;
    // What lit the frame, for compare's check that its frames belong together.
    const ImageAttributes attributes = {
        {"ocean:caustics", options.caustics ? "plugin" : "off"},
        {"ocean:objectCaustics", options.objectCaustics ? "plugin" : "off"},
        {"ocean:exposure", exposureAttribute(renderer.settings().exposure)}};
    if (!writeImage(name, options.width, options.height, renderer.readColor(), &radiance, error,
                    attributes))
      return commandFailed(error);
    if (!previous.empty()) {
      const double change = relativeFrameChange(previous, radiance);
      changeSum += change;
      changeMax = std::max(changeMax, change);
      std::printf("frame %d: %s, change from the previous frame %.5f\n", frame, name.c_str(),
                  change);
    } else if (sequence) {
      std::printf("frame 0: %s\n", name.c_str());
    }
    previous = std::move(radiance);
  }
  if (animation) {
    if (!writeAnimation(options.out, options.width, options.height, animationFrames, options.fps,
                        error))
      return commandFailed(error);
    std::printf("%s: %d frames at %g fps (GIF stores whole hundredths of a second)\n",
                options.out.c_str(), options.frames, animationFps(options.fps));
  }
  if (sequence || (animation && options.frames > 1)) {
    std::printf(
        "frame-to-frame change: mean %.5f, max %.5f (mean |luminance difference| / mean "
        "luminance) over %d frames at %g fps\n",
        changeSum / (options.frames - 1), changeMax, options.frames, options.fps);
  }
  return 0;
}

}  // namespace ocean
