// ocean_sample view: the scene in a window with a fly camera, feature toggles and an overlay
// (view_overlay.h) that shows the plugin's per-pass GPU timings and edits its settings live.
// With --frames N it draws N frames on a fixed clock and quits; --screenshot saves the last one.
// On local water (the pool preset) a click drops water where it points.
#include <epoxy/gl.h>
// epoxy loads GL; GLFW must not pull in the system GL header after it.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "camera.h"
#include "commands.h"
#include "image_output.h"
#include "live_settings.h"
#include "local_water_setup.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "scene_setup.h"
#include "view_flags.h"
#include "view_overlay.h"
#include "water_pick.h"

namespace ocean {
namespace {

struct ViewState {
  Preset preset;
  FrameInput input;
  LiveSettings settings;  // the keys and the overlay edit settings.edited
  bool paused = false;
  bool overlayVisible = true;
  bool dragging = false;
  double lastX = 0.0, lastY = 0.0;
  // A click (press and release within kClickPixels, not on the overlay) on local water drops
  // water there; a longer drag only turns the camera.
  bool pressed = false;
  double pressX = 0.0, pressY = 0.0, dragPixels = 0.0;
  bool clicked = false;
  double clickX = 0.0, clickY = 0.0;
  bool presetRequested = false;
  bool screenshotRequested = false;  // P: save this frame to --screenshot
  std::string presetName;
  const ViewOverlay* overlay = nullptr;
};

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  auto* state = static_cast<ViewState*>(glfwGetWindowUserPointer(window));
  // A text field of the overlay has the keyboard: the keys are its characters.
  if (state->overlay != nullptr && state->overlayVisible && state->overlay->capturesKeyboard())
    return;
  static const char* const kPresets[] = {"seabed", "sunward", "above", "waterline", "shallow"};
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (key == GLFW_KEY_T) state->paused = !state->paused;
  if (key == GLFW_KEY_H) state->overlayVisible = !state->overlayVisible;
  if (key == GLFW_KEY_P) state->screenshotRequested = true;
  if (key == GLFW_KEY_C) {
    state->settings.edited.caustics.enabled = !state->settings.edited.caustics.enabled;
    state->settings.untried = true;
  }
  if (key == GLFW_KEY_G) {
    state->settings.edited.godRays.enabled = !state->settings.edited.godRays.enabled;
    state->settings.untried = true;
  }
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_5) {
    state->presetName = kPresets[key - GLFW_KEY_1];
    state->presetRequested = true;
  }
}

void moveCamera(GLFWwindow* window, ViewState& state, double dt) {
  Camera& camera = state.input.camera;
  const glm::dvec3 forward = camera.forward();
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
  const double speed = (glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 12.0 : 3.0) * dt;
  const bool keys =
      state.overlay == nullptr || !state.overlayVisible || !state.overlay->capturesKeyboard();
  if (keys && glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) camera.position += forward * speed;
  if (keys && glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) camera.position -= forward * speed;
  if (keys && glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) camera.position += right * speed;
  if (keys && glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) camera.position -= right * speed;
  if (keys && glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) camera.position.y += speed;
  if (keys && glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) camera.position.y -= speed;
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  // A drag that starts on the overlay moves its widgets, not the camera.
  const bool overOverlay =
      state.overlay != nullptr && state.overlayVisible && state.overlay->capturesMouse();
  const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  if (pressed && state.dragging) {
    camera.yaw -= (x - state.lastX) * 0.004;
    camera.pitch = glm::clamp(camera.pitch - (y - state.lastY) * 0.004, -1.5, 1.5);
  }
  state.dragging = pressed && (state.dragging || !overOverlay);
  constexpr double kClickPixels = 4.0;
  if (pressed && !state.pressed) {
    state.pressX = x;
    state.pressY = y;
    state.dragPixels = overOverlay ? 1e9 : 0.0;  // a press on the overlay is never a drop
  }
  if (pressed) state.dragPixels += std::abs(x - state.lastX) + std::abs(y - state.lastY);
  if (!pressed && state.pressed && state.dragPixels < kClickPixels) {
    state.clicked = true;
    state.clickX = state.pressX;
    state.clickY = state.pressY;
  }
  state.pressed = pressed;
  state.lastX = x;
  state.lastY = y;
}

// A click on the water: a drop where its ray meets the mean level, if local water is there.
void dropAtClick(GLFWwindow* window, ViewState& state, Renderer& renderer) {
  if (!state.clicked) return;
  state.clicked = false;
  LocalWaterSource* water = renderer.localWater();
  int width = 0, height = 0;
  glfwGetWindowSize(window, &width, &height);
  if (water == nullptr || width <= 0 || height <= 0) return;
  // Window coordinates run down from the top left; NDC up from the centre.
  const glm::dvec2 ndc(2.0 * state.clickX / width - 1.0, 1.0 - 2.0 * state.clickY / height);
  glm::dvec2 xz;
  if (pickWaterPlane(state.input.camera, double(width) / height, ndc, renderer.optics().level, xz))
    water->addDrop(xz);
}

// The window's back buffer as shown (bottom row first, as writeImage takes it).
bool saveScreenshot(GLFWwindow* window, const std::string& path, std::string& error) {
  int width = 0, height = 0;
  glfwGetFramebufferSize(window, &width, &height);
  std::vector<uint8_t> pixels(size_t(width) * size_t(height) * 4);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
  glReadBuffer(GL_BACK);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, pixels.data());
  return writeImage(path, width, height, pixels, nullptr, error);
}

// The view's frames on an open window; returns the exit code.
int runFrames(GLFWwindow* window, const Options& options, ViewState& state, Renderer& renderer,
              PluginSetup& plugin, ViewOverlay* overlay) {
  std::string error, known;
  const ViewFeatures features{options.physicalCaustics, options.objectCaustics};
  const bool counted = options.frames > 0;
  double last = glfwGetTime(), titleTime = last, clock = options.timeSeconds;
  int runningFrames = 0;  // frames with the clock running
  for (int frame = 0; !glfwWindowShouldClose(window) && (!counted || frame < options.frames);
       ++frame) {
    glfwPollEvents();
    const double now = glfwGetTime();
    // Counted frames run on a fixed clock, so frame N is the same image on any machine.
    const double dt = counted ? 1.0 / options.fps : now - last;
    last = now;
    Preset requested;
    // The keys switch among the presets of the world the window was opened in (its scene is
    // built once): the sea's five, none from the pool or the wake.
    if (state.presetRequested &&
        (!findPreset(state.presetName, requested, known) || requested.scene != state.preset.scene))
      state.presetRequested = false;
    if (state.presetRequested) {
      state.preset = requested;
      state.input.camera = state.preset.camera;
      // A preset's sun is one the plugin takes: set it in both, so that it shows even while
      // an edit is refused.
      state.settings.edited.sun = state.preset.sun;
      state.settings.accepted.sun = state.preset.sun;
      // And the caustic settings its scene is shown with (the sea stays the start preset's).
      applyPresetCaustics(options, state.preset, state.settings.edited.caustics);
      state.settings.untried = true;
      state.presetRequested = false;
    }
    moveCamera(window, state, dt);
    dropAtClick(window, state, renderer);
    if (!state.paused && !options.freezeTime) {
      // Counted: the time render --frames gives its frame of the same number (sum-free).
      if (counted)
        clock = options.timeSeconds + runningFrames / options.fps;
      else
        clock += dt;
      ++runningFrames;
    }
    state.input.timeSeconds = clock;
    if (!renderLive(state.settings, plugin, renderer, state.input, error))
      return commandFailed(error);
    renderer.presentTo(0, options.width, options.height);
    if (overlay != nullptr && state.overlayVisible) {
      const ViewStatus status{state.preset.name.data(), state.input.timeSeconds, state.paused,
                              &state.settings.refusal};
      if (overlay->draw(plugin.stats(), status, features, state.settings.edited))
        state.settings.untried = true;
    }
    const bool lastFrame = counted && frame + 1 == options.frames;
    if ((lastFrame || state.screenshotRequested) && !options.screenshot.empty() &&
        !saveScreenshot(window, options.screenshot, error))
      return commandFailed(error);
    state.screenshotRequested = false;
    glfwSwapBuffers(window);
    if (overlay == nullptr && now - titleTime > 0.5) {
      glfwSetWindowTitle(window, ("ocean_sample  " + plugin.timingSummary()).c_str());
      titleTime = now;
    }
  }
  return 0;
}

}  // namespace

int runView(const Options& options) {
  std::string error;
  ViewState state;
  if (!resolveView(options, state.preset, error)) return commandFailed(error);
  // Before the window opens, so a bad path fails fast and leaves nothing behind.
  if (!options.screenshot.empty() && !checkOutputPath(options.screenshot, error))
    return commandFailed(error);
  ocean_scene::Model scene;
  if (!buildScene(options.models, scene, error, options.modelLimits, state.preset.scene,
                  state.preset.camera))
    return commandFailed(error);
  if (glfwInit() != GLFW_TRUE) return commandFailed("cannot initialise GLFW (no display?)");
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "ocean_sample", nullptr, nullptr);
  if (window == nullptr) {
    glfwTerminate();
    return commandFailed("cannot open an OpenGL 4.5 core window");
  }
  glfwMakeContextCurrent(window);
  // Counted frames have nothing to keep pace with.
  glfwSwapInterval(options.frames > 0 ? 0 : 1);
  int status = 0;
  {
    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.waterResolution = options.waterResolution;
    settings.exposure = float(std::exp2(state.preset.exposureStops));
    // The start preset's sea: switching presets with the keys keeps it (the FFT ocean is made
    // once per window).
    settings.windSpeed = state.preset.windSpeed;
    settings.airShadows = state.preset.airShadows;
    auto renderer = Renderer::create(settings, scene, error);
    // The start preset's lights (with --light) stay when keys switch presets.
    if (renderer) renderer->setLights(state.preset.lights);
    if (renderer && !attachLocalWater(state.preset, scene, *renderer, error)) renderer.reset();
    auto plugin = renderer
                      ? PluginSetup::create(*renderer, withPresetCaustics(options, state.preset),
                                            /*benchmarkFloor=*/false, error)
                      : nullptr;
    glfwSetWindowUserPointer(window, &state);
    glfwSetKeyCallback(window, onKey);
    std::unique_ptr<ViewOverlay> overlay;
    if (renderer && plugin && options.overlay) overlay = ViewOverlay::create(window, error);
    if (!renderer || !plugin || (options.overlay && !overlay)) {
      status = commandFailed(error);
    } else {
      state.overlay = overlay.get();
      state.settings.accepted = currentSettings(*plugin, *renderer, state.preset.sun);
      state.settings.edited = state.settings.accepted;
      state.input = {state.preset.camera, state.preset.sun, options.timeSeconds};
      status = runFrames(window, options, state, *renderer, *plugin, overlay.get());
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace ocean
