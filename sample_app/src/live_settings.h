#pragma once
// The view's settings as the user edits them and as the plugin last accepted them. An edit
// reaches the plugin with the next frame, and the plugin's validation alone decides: a refused
// edit stays (for the user to correct) beside the plugin's message, while the frames go on with
// the settings it accepted last.
#include <string>

#include "plugin_setup.h"
#include "renderer.h"
#include "view_settings.h"

namespace ocean {

struct LiveSettings {
  ViewSettings edited, accepted;
  bool untried = false;  // `edited` changed since it was last handed to the plugin
  std::string refusal;   // the plugin's message for the last edit it refused; empty once accepted
};

// What the plugin and the renderer hold now, with this sun.
ViewSettings currentSettings(PluginSetup& plugin, Renderer& renderer, const Sun& sun);

// Renders `input` with the edited settings when they are untried, else (or when the plugin
// refuses them: its validation, or a frame over its memory budget) with the accepted ones.
// False, with the message, only when the accepted settings fail too.
bool renderLive(LiveSettings& live, PluginSetup& plugin, Renderer& renderer, FrameInput& input,
                std::string& error);

}  // namespace ocean
