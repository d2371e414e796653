#include "headless_session.h"

#include <cmath>

#include "local_water_setup.h"
#include "scene_setup.h"
#include "view_flags.h"

namespace ocean {

bool openHeadlessSession(const Options& options, bool debug, bool benchmarkFloor,
                         HeadlessSession& session, std::string& error) {
  if (!resolveView(options, session.preset, error)) return false;
  ocean_scene::Model& scene = session.scene;
  if (!buildScene(options.models, scene, error, options.modelLimits, session.preset.scene,
                  session.preset.camera))
    return false;
  session.context = glcontext::HeadlessContext::create(debug, error);
  if (!session.context) return false;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (options.width > maxSize || options.height > maxSize) {
    error = "size " + std::to_string(options.width) + "x" + std::to_string(options.height) +
            " exceeds this GPU's limit of " + std::to_string(maxSize);
    return false;
  }
  RenderSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.waterResolution = options.waterResolution;
  settings.exposure = float(std::exp2(session.preset.exposureStops));
  settings.windSpeed = session.preset.windSpeed;
  settings.airShadows = session.preset.airShadows;
  session.renderer = Renderer::create(settings, scene, error);
  if (!session.renderer) return false;
  session.renderer->setLights(session.preset.lights);
  if (!attachLocalWater(session.preset, scene, *session.renderer, error)) return false;
  session.plugin = PluginSetup::create(
      *session.renderer, withPresetCaustics(options, session.preset), benchmarkFloor, error);
  return session.plugin != nullptr;
}

}  // namespace ocean
