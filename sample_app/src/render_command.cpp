// ocean_sample render: one headless frame to an image.
#include <cstdio>

#include <glcontext/context.h>

#include "camera.h"
#include "commands.h"
#include "headless_session.h"
#include "image_output.h"
#include "plugin_setup.h"
#include "renderer.h"

namespace ocean {
int runRender(const Options& options) {
  std::string error;
  // Checked before any work so a bad path fails fast and leaves nothing behind.
  if (!checkOutputPath(options.out, error)) return commandFailed(error);
  HeadlessSession session;
  if (!openHeadlessSession(options, /*debug=*/true, /*benchmarkFloor=*/false, session, error)) {
    return commandFailed(error);
  }
  const Preset& preset = session.preset;
  Renderer& renderer = *session.renderer;
  glcontext::HeadlessContext& context = *session.context;

  FrameInput input{preset.camera, preset.sun, options.timeSeconds};
  if (!renderer.render(input, error)) return commandFailed(error);
  for (const auto& message : context.debugLog().take()) {
    if (message.type == GL_DEBUG_TYPE_ERROR)
      return commandFailed(glcontext::debugMessageString(message));
  }
  const std::vector<float> radiance = renderer.readRadiance();
  if (!writeImage(options.out, options.width, options.height, renderer.readColor(), &radiance,
                  error)) {
    return commandFailed(error);
  }
  return 0;
}

}  // namespace ocean
