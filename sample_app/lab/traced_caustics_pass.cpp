#include "traced_caustics_pass.h"

#include <epoxy/gl.h>

#include "caustic_light_units.h"
#include "gbuffer_readback.h"
#include "local_water_readback.h"
#include "scene_triangles.h"
#include "water_readback.h"

namespace ocean {

reference::FrameTraceDesc frameTraceOptions(const Options& options) {
  reference::FrameTraceDesc desc;
  desc.seed = options.seed;
  desc.targetNoise = options.noise;
  desc.kernelScale = options.kernelScale;
  desc.minKernelRadius = options.minKernelRadius;
  desc.maxBatches = options.maxBatches;
  desc.threads = options.threads;
  return desc;
}

bool tracesReflectedLight(const postfx::CreateDesc& create, const postfx::FrameDesc& frame,
                          bool requested) {
  const postfx::ReflectedCausticsSettings& settings = frame.reflectedCaustics;
  const bool plugin =
      postfx::hasFeature(create.features, postfx::Feature::ReflectedCaustics) && settings.enabled;
  return (plugin || requested) && settings.intensity > 0.0f;
}

std::unique_ptr<TracedCausticsPass> TracedCausticsPass::create(
    const PluginSetup& plugin, const ocean_scene::Model& scene, const glm::dvec3& cameraPosition,
    const reference::FrameTraceDesc& trace, std::string& error) {
  std::unique_ptr<TracedCausticsPass> pass(new TracedCausticsPass());
  pass->plugin_ = &plugin;
  pass->trace_ = trace;
  pass->sceneOrigin_ = cameraPosition;
  const std::vector<reference::TriangleMesh> meshes = sceneTriangles(scene);
  if (!trace.casters.empty() && trace.casters.size() != meshes.size()) {
    error = "traced caustics: " + std::to_string(trace.casters.size()) + " caster entries for " +
            std::to_string(meshes.size()) + " meshes";
    return nullptr;
  }
  pass->scene_ = reference::EmbreeScene::create(meshes, cameraPosition, error);
  if (!pass->scene_) return nullptr;
  return pass;
}

bool TracedCausticsPass::run(const HostFrame& frame, std::string& error) {
  return addTo(frame.target, error);
}

bool TracedCausticsPass::addTo(GLuint target, std::string& error) {
  const postfx::FrameDesc& desc = plugin_->lastFrame();
  const postfx::CreateDesc& create = plugin_->createDesc();
  if (desc.camera.position != sceneOrigin_) {
    error = "traced caustics: the scene was built around another camera position";
    return false;
  }
  reference::GBufferCopy gbuffer;
  if (!reference::readGBuffer(create, desc, gbuffer, error)) return false;
  reference::WaterTextureSurface sea;
  if (!sea.read(desc.water, error)) return false;
  // The local water regions over the sea, where the frame has them: the trace refracts the water
  // the plugin was given.
  reference::LocalWaterSurface local;
  if (!local.read(desc.water, sea, error)) return false;
  const reference::Surface& water =
      local.regionCount() > 0 ? static_cast<const reference::Surface&>(local) : sea;
  receivers_ = reference::receiversOf(desc, gbuffer);
  reference::FrameTraceDesc trace = trace_;
  trace.towardSun = glm::normalize(desc.sun.direction);
  trace.ior = desc.water.ior;
  trace.sunAngularRadius = 0.5 * glm::radians(double(desc.sun.angularDiameterDegrees));
  trace.waterAbsorption = glm::dvec3(desc.water.absorption);
  trace.reflected = tracesReflectedLight(create, desc, trace_.reflected);
  // Nothing to trace under a sun below the horizon, unless local lights shine through casters.
  result_ = reference::traceFrameCaustics(water, *scene_, receivers_, trace);

  // Add the traced light into the host's HDR target, where the plugin would have added its own.
  const size_t n = receivers_.size();
  std::vector<glm::vec4> radiance(n);
  glGetTextureImage(target, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(n * sizeof(glm::vec4)),
                    radiance.data());
  const reference::CausticLightUnits units = reference::causticLightUnits(desc);
  const bool objects = !result_.objectIrradiance.empty();
  const bool locals = !result_.localIrradiance.empty();
  const bool mirrored = !result_.reflectedIrradiance.empty();
  for (size_t i = 0; i < n && !result_.irradiance.empty(); ++i) {
    const double viewDistance = glm::length(gbuffer.viewPosition[i]);
    if (mirrored && receivers_.above[i] && result_.reflectedIrradiance[i] != 0.0) {
      // Flat water's mirror light where it reaches the point: what a host lighting with a
      // mirrored sun already holds (taken off without includeMirrorMean).
      const double flat = result_.reflectedLit[i] ? result_.flatReflected[i] : 0.0;
      const glm::vec3 light =
          reference::referenceReflectedLight(units, gbuffer.albedo[i], receivers_.depthBelow(i),
                                             result_.reflectedIrradiance[i], flat, viewDistance);
      radiance[i] += glm::vec4(light, 0.0f);
    }
    if (!receivers_.valid[i]) continue;
    if (result_.irradiance[i] > 0.0) {
      const glm::vec3 light = reference::referenceCausticLight(
          units, gbuffer.albedo[i], receivers_.depthBelow(i), result_.irradiance[i], viewDistance);
      radiance[i] += glm::vec4(light, 0.0f);
    }
    if (objects && result_.objectIrradiance[i] != glm::dvec3(0.0)) {
      const glm::vec3 light =
          reference::referenceObjectCausticLight(units, gbuffer.albedo[i], receivers_.depthBelow(i),
                                                 result_.objectIrradiance[i], viewDistance);
      radiance[i] += glm::vec4(light, 0.0f);
    }
    if (locals && result_.localIrradiance[i] != glm::dvec3(0.0)) {
      const glm::vec3 light =
          reference::referenceLocalCausticLight(units, gbuffer.albedo[i], receivers_.depthBelow(i),
                                                result_.localIrradiance[i], viewDistance);
      radiance[i] += glm::vec4(light, 0.0f);
    }
  }
  glTextureSubImage2D(target, 0, 0, 0, receivers_.width, receivers_.height, GL_RGBA, GL_FLOAT,
                      radiance.data());
  return true;
}

}  // namespace ocean
