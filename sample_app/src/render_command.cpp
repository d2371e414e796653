// ocean_sample render: one headless frame to an image.
#include <cstdio>

#include <glcontext/context.h>

#include "camera.h"
#include "commands.h"
#include "image_output.h"
#include "plugin_setup.h"
#include "renderer.h"
#include "scene_setup.h"

namespace ocean {
namespace {

int fail(const std::string& message) {
  std::fprintf(stderr, "ocean_sample: %s\n", message.c_str());
  return 1;
}

}  // namespace

int runRender(const Options& options) {
  std::string error, known;
  Preset preset;
  if (!findPreset(options.preset, preset, known)) {
    return fail("unknown preset '" + options.preset + "' (known: " + known + ")");
  }
  if (!checkOutputPath(options.out, error)) return fail(error);
  ocean_scene::Model scene;
  if (!buildScene(options.models, scene, error)) return fail(error);

  auto context = glcontext::HeadlessContext::create(/*debug=*/true, error);
  if (!context) return fail(error);
  RenderSettings settings;
  settings.width = options.width;
  settings.height = options.height;
  settings.waterResolution = options.waterResolution;
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &maxSize);
  if (settings.width > maxSize || settings.height > maxSize) {
    return fail("size " + std::to_string(settings.width) + "x" + std::to_string(settings.height) +
                " exceeds this GPU's limit of " + std::to_string(maxSize));
  }
  auto renderer = Renderer::create(settings, scene, error);
  if (!renderer) return fail(error);
  auto plugin = PluginSetup::create(*renderer, options, /*benchmarkFloor=*/false, error);
  if (!plugin) return fail(error);

  FrameInput input{preset.camera, preset.sun, options.timeSeconds};
  if (!renderer->render(input, error)) return fail(error);
  for (const auto& message : context->debugLog().take()) {
    if (message.type == GL_DEBUG_TYPE_ERROR) return fail(glcontext::debugMessageString(message));
  }
  const std::vector<float> radiance = renderer->readRadiance();
  if (!writeImage(options.out, settings.width, settings.height, renderer->readColor(), &radiance,
                  error)) {
    return fail(error);
  }
  return 0;
}

}  // namespace ocean
