#pragma once
// The view's Dear ImGui overlay (Debian's libimgui, its GLFW and OpenGL 3 backends): the
// plugin's per-pass GPU timings as they arrive and the panel that edits the live settings.
// It writes and reads no file (no imgui.ini, no log).
#include <memory>
#include <string>

#include <postfx/diagnostics.h>

#include "view_settings_panel.h"

struct GLFWwindow;

namespace ocean {

// What the overlay shows beside the settings.
struct ViewStatus {
  const char* preset = "";
  double timeSeconds = 0.0;
  bool paused = false;
  // The plugin's message for the last edit it refused (empty when the last one was accepted);
  // the frame shows the last accepted settings meanwhile.
  const std::string* refusal = nullptr;
};

class ViewOverlay {
 public:
  // Call after the window's own input callbacks are installed: ImGui's chain to them. Null with
  // a message when the backends cannot start on this context.
  static std::unique_ptr<ViewOverlay> create(GLFWwindow* window, std::string& error);
  ~ViewOverlay();
  ViewOverlay(const ViewOverlay&) = delete;
  ViewOverlay& operator=(const ViewOverlay&) = delete;

  // True while a widget has the keyboard or the mouse is over the overlay: the view's own keys
  // and mouse look leave that input to it.
  bool capturesKeyboard() const;
  bool capturesMouse() const;

  // Draws into the window's framebuffer over what is there; returns true when the user changed
  // `settings`. GL state is left as it was (the backend saves and restores it).
  bool draw(const postfx::FrameStats& stats, const ViewStatus& status, const ViewFeatures& features,
            ViewSettings& settings);

 private:
  ViewOverlay() = default;
  bool started_ = false;  // the ImGui context and both backends are up
};

}  // namespace ocean
