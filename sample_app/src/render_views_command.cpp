// ocean_sample render --views N / --stereo / --cube-map: several views of one frame, handed to
// the plugin in one dispatch (its view-independent pre-passes once), written as one image: the
// views side by side (split-screen, or a stereo pair), or the six faces of a cube-map probe at
// the camera as a 4x3 cross.
// With --frames N > 1 an image sequence, as render writes one.
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "camera.h"
#include "commands.h"
#include "frame_sequence.h"
#include "headless_session.h"
#include "image_output.h"
#include "multi_view.h"

namespace ocean {
namespace {

// View i of a split-screen: the preset's camera, the next ones 4 m to its right each, turned
// 0.5 rad back toward where the first looks.
Camera splitCamera(const Camera& first, int i) {
  Camera c = first;
  const glm::dvec3 right = first.rotation()[0];
  c.position += right * (4.0 * i);
  c.yaw += 0.5 * i;
  return c;
}

// A stereo pair: parallel eyes `interocular` apart about the camera, left eye first.
Camera eyeCamera(const Camera& head, int eye) {
  constexpr double kInterocular = 0.064;  // m: an adult's typical distance between the pupils
  Camera c = head;
  c.position += head.rotation()[0] * (kInterocular * (eye == 0 ? -0.5 : 0.5));
  return c;
}

}  // namespace

int runRenderViews(const Options& commandOptions) {
  std::string error;
  std::string extension = std::filesystem::path(commandOptions.out).extension().string();
  for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".gif")
    return commandFailed("render --views/--cube-map writes PNG or EXR images, not an animation");
  const bool cube = commandOptions.cubeMap, stereo = commandOptions.stereo;
  if (int(cube) + int(stereo) + int(commandOptions.views > 1) > 1)
    return commandFailed("render takes one of --views N, --stereo and --cube-map");
  const int count = cube ? 6 : stereo ? 2 : commandOptions.views;
  // Each view's size: a column of the image, or a cube face of a quarter of its width.
  Options options = commandOptions;
  if (cube) {
    // The cross is 4 faces wide and 3 tall: its size follows from --width alone.
    if (commandOptions.heightGiven)
      return commandFailed("render --cube-map takes no --height (got " +
                           std::to_string(commandOptions.height) +
                           "): the cross is 4 faces of --width/4 wide and 3 tall, so --width " +
                           std::to_string(commandOptions.width) + " makes it " +
                           std::to_string(commandOptions.width) + "x" +
                           std::to_string(commandOptions.width / 4 * 3) + "; give --width only");
    if (commandOptions.width < 4 || commandOptions.width % 4 != 0)
      return commandFailed(
          "render --cube-map needs a --width that 4 divides (each of the "
          "cross's 4 columns is a cube face), got " +
          std::to_string(commandOptions.width) + ": try --width " +
          std::to_string(std::max(4, commandOptions.width / 4 * 4)));
    options.width = options.height = commandOptions.width / 4;
  } else {
    if (commandOptions.width % count != 0)
      return commandFailed(std::string("render ") +
                           (stereo ? "--stereo" : "--views " + std::to_string(count)) +
                           " needs a --width that " + std::to_string(count) + " divides, got " +
                           std::to_string(commandOptions.width));
    options.width = commandOptions.width / count;
  }
  const int outWidth = cube ? options.width * 4 : commandOptions.width;
  const int outHeight = cube ? options.height * 3 : options.height;
  const bool sequence = options.frames > 1;
  const std::string firstName =
      sequence ? sequenceFrameName(options.out, 0, options.frames) : options.out;
  if (!checkOutputPath(firstName, error)) return commandFailed(error);

  HeadlessSession session;
  if (!openHeadlessSession(options, /*debug=*/true, /*benchmarkFloor=*/false, session, error))
    return commandFailed(error);
  if (cube) session.preset.camera.fovY = glm::radians(90.0);
  auto views = MultiView::create(*session.renderer, session.scene, count, error);
  if (!views) return commandFailed(error);
  for (int frame = 0; frame < options.frames; ++frame) {
    const double seconds = frame / options.fps;
    Camera first;
    if (!cameraAt(options, session.preset.camera, seconds, first))
      return commandFailed("the camera path leaves 1e7 m from the origin at " +
                           std::to_string(seconds) + " s");
    const std::vector<Camera> cameras = [&] {
      if (cube) return cubeFaceCameras(first.position);
      std::vector<Camera> split;
      for (int i = 0; i < count; ++i)
        split.push_back(stereo ? eyeCamera(first, i) : splitCamera(first, i));
      return split;
    }();
    std::vector<FrameInput> inputs;
    for (const Camera& camera : cameras)
      inputs.push_back(
          {camera, session.preset.sun, options.timeSeconds + (options.freezeTime ? 0.0 : seconds)});
    if (!views->render(inputs, *session.plugin, &session.context->debugLog(), error))
      return commandFailed(error);
    std::vector<std::vector<float>> radiance;
    std::vector<std::vector<uint8_t>> color;
    for (int i = 0; i < count; ++i) {
      radiance.push_back(views->view(i).readRadiance());
      color.push_back(views->view(i).readColor());
    }
    std::vector<float> image;
    std::vector<uint8_t> colorImage;
    if (cube) {
      image = cubeCross(radiance, options.width);
      std::vector<std::vector<float>> asFloat;
      for (const auto& c : color) asFloat.emplace_back(c.begin(), c.end());
      const std::vector<float> cross = cubeCross(asFloat, options.width);
      colorImage.assign(cross.begin(), cross.end());
    } else {
      image = sideBySide(radiance, options.width, options.height);
      colorImage = sideBySide(color, options.width, options.height);
    }
    const std::string name =
        sequence ? sequenceFrameName(options.out, frame, options.frames) : options.out;
    const ImageAttributes attributes = {
        {"ocean:views", cube     ? "cube-map"
                        : stereo ? "stereo"
                                 : std::to_string(count)},
        {"ocean:exposure", exposureAttribute(session.renderer->settings().exposure)}};
    if (!writeImage(name, outWidth, outHeight, colorImage, &image, error, attributes))
      return commandFailed(error);
    std::printf("%s: %d views in one plugin dispatch (%s)\n", name.c_str(), count,
                cube     ? "cube-map cross, faces +X -X +Y -Y +Z -Z"
                : stereo ? "stereo pair, left eye on the left"
                         : "side by side");
  }
  return 0;
}

}  // namespace ocean
