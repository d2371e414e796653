#include "frame_estimate.h"

#include <epoxy/gl.h>

#include <map>

#include <shader_statistics.h>

#include "plugin_setup.h"

namespace ocean {

bool renderFrames(HeadlessSession& session, const Options& options, int frames,
                  std::string& error) {
  FrameInput input{session.preset.camera, session.preset.sun, options.timeSeconds};
  for (int frame = 0; frame <= frames; ++frame) {
    if (frame == frames) glFinish();
    input.timeSeconds = options.timeSeconds + frame / 60.0;
    if (!session.renderer->render(input, error)) return false;
  }
  return true;
}

bool usePlugin(HeadlessSession& session, Options options, Options::WorkAccount mode, bool floor,
               std::string& error) {
  options.workAccount = mode;
  session.plugin.reset();
  session.plugin = PluginSetup::create(*session.renderer, options, floor, error);
  return session.plugin != nullptr;
}

bool estimatePasses(HeadlessSession& session, const Options& options, const cost::GpuClass& gpu,
                    double toPixels, bool floor, std::array<double, postfx::kPassCount>& out,
                    std::string& error) {
  out.fill(0.0);
  std::map<std::string, cost::ProgramStatistics> programs;
  {
    // The driver's dump of the plain context's programs (the counting context's are
    // instrumented): their arithmetic.
    cost::ShaderDumpCapture capture;
    if (!usePlugin(session, options, Options::WorkAccount::Off, false, error) ||
        !renderFrames(session, options, 1, error))
      return false;
    programs = cost::labelled(cost::parseNirDump(capture.text()));
  }
  if (!usePlugin(session, options, Options::WorkAccount::Counted, false, error) ||
      !renderFrames(session, options, 1, error))
    return false;
  out = cost::passEstimatesMs(session.plugin->workSteps(), programs, gpu,
                              double(options.width) * double(options.height), toPixels);
  return usePlugin(session, options, Options::WorkAccount::Off, floor, error);
}

}  // namespace ocean
