#pragma once
// What every headless command starts with: the preset, the scene, an EGL context, the
// renderer and the plugin, each step failing with a message that names the problem.
#include <memory>
#include <string>

#include <glcontext/context.h>
#include <scene/model.h>

#include "camera.h"
#include "options.h"
#include "plugin_setup.h"
#include "renderer.h"

namespace ocean {

struct HeadlessSession {
  Preset preset;
  ocean_scene::Model scene;  // what the renderer drew (the traced reference intersects it)
  // Declared in creation order: destroyed plugin first, GL context last.
  std::unique_ptr<glcontext::HeadlessContext> context;
  std::unique_ptr<Renderer> renderer;
  std::unique_ptr<PluginSetup> plugin;
};

// debug: collect KHR_debug messages (render fails on any GL error); benchmarkFloor: also run
// the plugin's floor pass (bench).
bool openHeadlessSession(const Options& options, bool debug, bool benchmarkFloor,
                         HeadlessSession& session, std::string& error);

}  // namespace ocean
