// ocean_sample view: the scene in a window with a fly camera and feature toggles. The per-pass
// GPU timings of the plugin show in the title bar (no text renderer needed).
#include <epoxy/gl.h>
// epoxy loads GL; GLFW must not pull in the system GL header after it.
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>

#include "camera.h"
#include "commands.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "scene_setup.h"
#include "view_flags.h"

namespace ocean {
namespace {

struct ViewState {
  Preset preset;
  FrameInput input;
  bool paused = false;
  bool causticsEnabled = true;
  bool godRaysEnabled = true;
  bool dragging = false;
  double lastX = 0.0, lastY = 0.0;
  bool presetRequested = false;
  std::string presetName;
};

void onKey(GLFWwindow* window, int key, int, int action, int) {
  if (action != GLFW_PRESS) return;
  auto* state = static_cast<ViewState*>(glfwGetWindowUserPointer(window));
  static const char* const kPresets[] = {"seabed", "sunward", "above", "waterline"};
  if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(window, GLFW_TRUE);
  if (key == GLFW_KEY_T) state->paused = !state->paused;
  if (key == GLFW_KEY_C) state->causticsEnabled = !state->causticsEnabled;
  if (key == GLFW_KEY_G) state->godRaysEnabled = !state->godRaysEnabled;
  if (key >= GLFW_KEY_1 && key <= GLFW_KEY_4) {
    state->presetName = kPresets[key - GLFW_KEY_1];
    state->presetRequested = true;
  }
}

void moveCamera(GLFWwindow* window, ViewState& state, double dt) {
  Camera& camera = state.input.camera;
  const glm::dvec3 forward = camera.forward();
  const glm::dvec3 right = glm::normalize(glm::cross(forward, glm::dvec3(0, 1, 0)));
  const double speed = (glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ? 12.0 : 3.0) * dt;
  if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) camera.position += forward * speed;
  if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) camera.position -= forward * speed;
  if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) camera.position += right * speed;
  if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) camera.position -= right * speed;
  if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) camera.position.y += speed;
  if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) camera.position.y -= speed;
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  const bool pressed = glfwGetMouseButton(window, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
  if (pressed && state.dragging) {
    camera.yaw -= (x - state.lastX) * 0.004;
    camera.pitch = glm::clamp(camera.pitch - (y - state.lastY) * 0.004, -1.5, 1.5);
  }
  state.dragging = pressed;
  state.lastX = x;
  state.lastY = y;
}

}  // namespace

int runView(const Options& options) {
  std::string error, known;
  ViewState state;
  if (!resolveView(options, state.preset, error)) return commandFailed(error);
  ocean_scene::Model scene;
  if (!buildScene(options.models, scene, error)) {
    return commandFailed(error);
  }
  if (glfwInit() != GLFW_TRUE) {
    std::fprintf(stderr, "ocean_sample: cannot initialise GLFW (no display?)\n");
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_FALSE);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "ocean_sample", nullptr, nullptr);
  if (window == nullptr) {
    std::fprintf(stderr, "ocean_sample: cannot open an OpenGL 4.5 core window\n");
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  glfwSwapInterval(1);
  int status = 0;
  {
    RenderSettings settings;
    settings.width = options.width;
    settings.height = options.height;
    settings.waterResolution = options.waterResolution;
    auto renderer = Renderer::create(settings, scene, error);
    auto plugin = renderer
                      ? PluginSetup::create(*renderer, options, /*benchmarkFloor=*/false, error)
                      : nullptr;
    if (!renderer || !plugin) {
      status = commandFailed(error);
    } else {
      state.input = {state.preset.camera, state.preset.sun, options.timeSeconds};
      state.causticsEnabled = options.caustics;
      state.godRaysEnabled = options.godRays;
      glfwSetWindowUserPointer(window, &state);
      glfwSetKeyCallback(window, onKey);
      double last = glfwGetTime(), titleTime = last;
      while (!glfwWindowShouldClose(window) && status == 0) {
        glfwPollEvents();
        const double now = glfwGetTime();
        if (state.presetRequested) {
          findPreset(state.presetName, state.preset, known);
          state.input.camera = state.preset.camera;
          state.input.sun = state.preset.sun;
          state.presetRequested = false;
        }
        moveCamera(window, state, now - last);
        if (!state.paused) state.input.timeSeconds += now - last;
        plugin->caustics().enabled = state.causticsEnabled;
        plugin->godRays().enabled = state.godRaysEnabled;
        last = now;
        if (!renderer->render(state.input, error)) {
          status = commandFailed(error);
        }
        renderer->presentTo(0, options.width, options.height);
        glfwSwapBuffers(window);
        if (now - titleTime > 0.5) {
          glfwSetWindowTitle(window, ("ocean_sample  " + plugin->timingSummary()).c_str());
          titleTime = now;
        }
      }
    }
  }
  glfwDestroyWindow(window);
  glfwTerminate();
  return status;
}

}  // namespace ocean
