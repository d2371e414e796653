// ocean_sample reference: the frame `render` draws, with the plugin's seabed caustic light
// replaced by traced caustic light in the same units (see TracedCausticsPass and --help): the
// seabed's, with object caustics on (the default) the light of the glass and metal casters, and
// with reflected caustics on (the harbour) the sunlight the waves reflect above the water.
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include <glcontext/context.h>

#include "commands.h"
#include "headless_session.h"
#include "image_output.h"
#include "scene_triangles.h"
#include "traced_caustics_pass.h"

namespace ocean {
namespace {

// The object-caustics region `compare` judges apart: the casters' shadows, and wherever the
// traced light through or off the casters is at least this share of flat water's.
constexpr double kObjectRegionIrradiance = 0.05;

reference::FrameTraceDesc traceDesc(const Options& options) {
  reference::FrameTraceDesc desc = frameTraceOptions(options);
  desc.progress = [](const reference::FrameTraceProgress& p) {
    char reflected[160] = "";
    if (p.reflected)
      std::snprintf(reflected, sizeof(reflected),
                    " (of which reflected above the water, %zu mirror-lit pixels: median %.2f %%, "
                    "p99 %.2f %%, max %.2f %%)",
                    p.reflectedLitPixels, 100.0 * p.reflectedNoiseMedian,
                    100.0 * p.reflectedNoiseQuantile, 100.0 * p.reflectedNoiseMax);
    std::printf(
        "reference: batch %d, %.3g photons, lit-pixel noise median %.2f %%, p99 %.2f %%, max "
        "%.2f %%%s, %.1f s%s\n",
        p.batch, static_cast<double>(p.photons), 100.0 * p.noiseMedian, 100.0 * p.noiseQuantile,
        100.0 * p.noiseMax, reflected, p.seconds,
        p.done ? (p.converged ? ", converged" : ", BATCH CAP REACHED (not converged)") : "");
    std::fflush(stdout);
  };
  return desc;
}

}  // namespace

int runReference(const Options& options) {
  std::string error;
  if (!checkOutputPath(options.out, error)) return commandFailed(error);
  if (std::filesystem::path(options.out).extension() != ".exr")
    return commandFailed("reference writes linear radiance: --out must end in .exr, got '" +
                         options.out + "'");
  // The plugin runs with its own caustics off, seabed and object; the traced light takes their
  // place.
  Options frameOptions = options;
  frameOptions.caustics = false;
  frameOptions.objectCaustics = false;
  HeadlessSession session;
  if (!openHeadlessSession(frameOptions, /*debug=*/true, /*benchmarkFloor=*/false, session,
                           error)) {
    return commandFailed(error);
  }
  Renderer& renderer = *session.renderer;
  const FrameInput input{session.preset.camera, session.preset.sun, options.timeSeconds};
  reference::FrameTraceDesc trace = traceDesc(options);
  // Reflected caustics where the run has them (the preset's choice or the flag): the plugin's
  // own pass off, its settings kept (their intensity is the traced light's unit), and the trace
  // reflects its photons too.
  if (postfx::hasFeature(session.plugin->createDesc().features,
                         postfx::Feature::ReflectedCaustics)) {
    session.plugin->reflectedCaustics().enabled = false;
    trace.reflected = true;
  }
  if (options.objectCaustics) {
    trace.casters = sceneCasterMaterials(session.scene);
    for (const HostLight& host : renderer.lights()) {
      const SceneLight& l = host.light;
      reference::TracedLight light;
      light.position = l.position;
      light.axis = glm::normalize(l.direction);
      light.spot = l.type == SceneLight::Type::Spot;
      light.outerHalfAngle = 0.5 * glm::radians(double(l.coneAngleDegrees));
      light.innerHalfAngle = light.outerHalfAngle * (1.0 - double(l.coneSoftness));
      light.intensity = glm::dvec3(l.intensity);
      light.range = l.range;
      trace.lights.push_back(light);
    }
  }
  size_t casters = 0;
  for (const auto& caster : trace.casters) casters += caster.has_value() ? 1 : 0;
  auto traced = TracedCausticsPass::create(*session.plugin, session.scene, input.camera.position,
                                           trace, error);
  if (!traced) return commandFailed(error);
  std::printf("reference: %zu triangles in Embree (%zu glass/metal casters traced), %dx%d pixels\n",
              traced->triangleCount(), casters, options.width, options.height);
  const PluginPass plugin = renderer.pluginPass();
  TracedCausticsPass* pass = traced.get();
  renderer.setPluginPass([plugin, pass](const HostFrame& frame, std::string& message) {
    return plugin(frame, message) && pass->run(frame, message);
  });
  if (!renderer.render(input, error)) return commandFailed(error);
  for (const auto& message : session.context->debugLog().take()) {
    if (message.type == GL_DEBUG_TYPE_ERROR)
      return commandFailed(glcontext::debugMessageString(message));
  }
  const reference::FrameTraceResult& result = pass->result();
  const std::vector<float> radiance = renderer.readRadiance();
  const size_t n = static_cast<size_t>(options.width) * static_cast<size_t>(options.height);
  std::vector<std::string> channels = {"R",
                                       "G",
                                       "B",
                                       "A",
                                       "caustic.E",
                                       "caustic.noise",
                                       "caustic.lit",
                                       "caustic.objectE",
                                       "caustic.objectRegion",
                                       "caustic.localE"};
  // The reflected light above the water, where it was traced (flat sea on a downward face = 1).
  const bool reflected = !result.reflectedIrradiance.empty();
  const size_t reflectedChannel = channels.size();
  if (reflected) {
    for (const char* name :
         {"caustic.reflectedE", "caustic.reflectedNoise", "caustic.reflectedLit"})
      channels.push_back(name);
  }
  size_t mirrorPixels = 0;
  double mirrorSum = 0.0, mirrorPeak = 0.0;  // traced reflected light over the mirror-lit pixels
  size_t regionPixels = 0;
  double regionSum = 0.0, regionPeak = 0.0;  // traced object light over the region
  std::vector<float> pixels(n * channels.size(), 0.0f);
  // Local lights' caustics count toward the region where they reach this share of the lights'
  // direct light (or of its median, where the direct light is dimmer).
  const double directMedian = result.localDirectMedian;
  for (size_t i = 0; i < n; ++i) {
    float* out = &pixels[i * channels.size()];
    for (int c = 0; c < 4; ++c) out[c] = radiance[4 * i + static_cast<size_t>(c)];
    if (i < result.irradiance.size()) {
      out[4] = static_cast<float>(result.irradiance[i]);
      out[5] = static_cast<float>(result.noise[i]);
      out[6] = result.lit[i] ? 1.0f : 0.0f;
    }
    if (i < result.objectIrradiance.size()) {
      const glm::dvec3& e = result.objectIrradiance[i];
      const double mean = (e.x + e.y + e.z) / 3.0;
      out[7] = static_cast<float>(mean);
      bool region = result.casterShadow[i] != 0 || mean >= kObjectRegionIrradiance;
      if (i < result.localIrradiance.size()) {
        const glm::dvec3& l = result.localIrradiance[i];
        const double local = (l.x + l.y + l.z) / 3.0;
        out[9] = static_cast<float>(local);
        region = region ||
                 (local > 0.0 &&
                  local >= kObjectRegionIrradiance * std::max(result.localDirect[i], directMedian));
      }
      out[8] = region ? 1.0f : 0.0f;
      if (region) {
        ++regionPixels;
        regionSum += mean;
        regionPeak = std::max(regionPeak, mean);
      }
    }
    if (reflected && i < result.reflectedIrradiance.size()) {
      out[reflectedChannel] = static_cast<float>(result.reflectedIrradiance[i]);
      out[reflectedChannel + 1] = static_cast<float>(result.reflectedNoise[i]);
      out[reflectedChannel + 2] = result.reflectedLit[i] ? 1.0f : 0.0f;
      if (result.reflectedLit[i]) {
        ++mirrorPixels;
        mirrorSum += result.reflectedIrradiance[i];
        mirrorPeak = std::max(mirrorPeak, result.reflectedIrradiance[i]);
      }
    }
  }
  const ImageAttributes attributes = {
      {"ocean:caustics", "traced"},
      {"ocean:objectCaustics", options.objectCaustics ? "traced" : "off"},
      {"ocean:reflectedCaustics", reflected ? "traced" : "off"},
      {"ocean:exposure", exposureAttribute(renderer.settings().exposure)}};
  if (!writeExrChannels(options.out, options.width, options.height, channels, pixels, error,
                        attributes))
    return commandFailed(error);
  std::printf(
      "reference: %s: %zu lit underwater pixels, %.3g photons in %d batches, noise median "
      "%.2f %% p99 %.2f %% max %.2f %%, %s, trace %.1f s\n",
      options.out.c_str(), result.litPixels, static_cast<double>(result.photons), result.batches,
      100.0 * result.noiseMedian, 100.0 * result.noiseQuantile, 100.0 * result.noiseMax,
      result.converged ? "converged" : "NOT converged", result.seconds);
  if (casters > 0)
    std::printf(
        "reference: object caustics: %zu pixels in the casters' shadows, %zu in the "
        "object-caustics region (caustic.objectRegion); traced light through the casters there "
        "(caustic.objectE, flat water = 1): mean %.4f, peak %.4f\n",
        result.casterShadowPixels, regionPixels,
        regionPixels > 0 ? regionSum / static_cast<double>(regionPixels) : 0.0, regionPeak);
  if (reflected)
    std::printf(
        "reference: reflected light above the water: %zu mirror-lit pixels (caustic.reflectedLit), "
        "%.3g of the photons per batch, noise median %.2f %% p99 %.2f %% max %.2f %%; traced "
        "reflected light there (caustic.reflectedE, flat sea on a downward face = 1): mean %.4f, "
        "peak %.4f; photons at the back of a wave %.3g, mirrored back into the water %.3g, "
        "mirrored again by a later wave %.3g\n",
        result.reflectedLitPixels, static_cast<double>(result.reflectedPhotonsPerBatch),
        100.0 * result.reflectedNoiseMedian, 100.0 * result.reflectedNoiseQuantile,
        100.0 * result.reflectedNoiseMax,
        mirrorPixels > 0 ? mirrorSum / static_cast<double>(mirrorPixels) : 0.0, mirrorPeak,
        static_cast<double>(result.reflectedBackOfWavePhotons),
        static_cast<double>(result.reflectedIntoWaterPhotons),
        static_cast<double>(result.reflectedReboundPhotons));
  if (!trace.lights.empty())
    std::printf(
        "reference: %zu local light(s) traced through the casters, %.3g photons per batch "
        "(caustic.localE: intensity / m^2; lights above the water are not traced)\n",
        trace.lights.size(), static_cast<double>(result.lightPhotonsPerBatch));
  return 0;
}

}  // namespace ocean
