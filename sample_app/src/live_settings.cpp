#include "live_settings.h"

namespace ocean {
namespace {

void apply(const ViewSettings& settings, PluginSetup& plugin, Renderer& renderer,
           FrameInput& input) {
  plugin.caustics() = settings.caustics;
  plugin.godRays() = settings.godRays;
  plugin.objectCaustics() = settings.objectCaustics;
  renderer.optics() = settings.optics;
  input.sun = settings.sun;
}

}  // namespace

ViewSettings currentSettings(PluginSetup& plugin, Renderer& renderer, const Sun& sun) {
  return {plugin.caustics(), plugin.godRays(), plugin.objectCaustics(), sun, renderer.optics()};
}

bool renderLive(LiveSettings& live, PluginSetup& plugin, Renderer& renderer, FrameInput& input,
                std::string& error) {
  if (live.untried) {
    live.untried = false;
    apply(live.edited, plugin, renderer, input);
    // A refused frame drew only the host's passes before the plugin; it is drawn again whole.
    std::string refusal;
    if (renderer.render(input, refusal)) {
      live.accepted = live.edited;
      live.refusal.clear();
      return true;
    }
    live.refusal = refusal;
  }
  apply(live.accepted, plugin, renderer, input);
  return renderer.render(input, error);
}

}  // namespace ocean
