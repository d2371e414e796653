#pragma once
// The pass that replaces the plugin's seabed caustics by traced light in a frame: it runs after
// the plugin (whose own caustics are off), reads back the frame's G-buffer and water texture,
// traces the sun through that water against the scene's triangles
// (reference::traceFrameCaustics) and adds, at every pixel under the water, the light the
// plugin's caustics pass would add there with its caustic factor replaced by the traced
// irradiance (reference::referenceCausticLight: the same units). The rest of the frame (fog,
// water surface, tone mapping) then runs unchanged. With casters in the trace
// (FrameTraceDesc::casters, from sceneCasterMaterials) it also adds the light they pass or
// reflect, where the plugin's object caustics would add theirs (which must then be off). With
// the plugin's reflected caustics on (Feature::ReflectedCaustics, enabled, intensity > 0) or
// asked for in the trace (FrameTraceDesc::reflected: the caller turned the plugin's own off), it
// also traces the light the water reflects up and adds it above the water where the plugin's
// reflected caustics would (reference::referenceReflectedLight: the same units, and only the
// waves' modulation without includeMirrorMean).
#include <memory>
#include <string>
#include <vector>

#include <scene/model.h>

#include "frame_caustics_reference.h"
#include "plugin_setup.h"
#include "renderer.h"

namespace ocean {

// The trace's settings the command line gives (--seed, --noise, --kernel, --min-kernel,
// --max-batches, --threads), without progress.
reference::FrameTraceDesc frameTraceOptions(const Options& options);

// Whether the traced pass traces the reflected light: the plugin draws it this frame
// (Feature::ReflectedCaustics and enabled) or the caller `requested` it, at an intensity above 0
// (the frame's ReflectedCausticsSettings, whose units it adds the light in).
bool tracesReflectedLight(const postfx::CreateDesc& create, const postfx::FrameDesc& frame,
                          bool requested);

class TracedCausticsPass {
 public:
  // `trace` without sun and IOR (taken from the frame; `reflected` asks for the reflected light
  // with the plugin's own off, see tracesReflectedLight); its casters, if any, one per mesh of
  // sceneTriangles(scene). Builds the Embree scene of `scene` around `cameraPosition` (the
  // frame's camera).
  static std::unique_ptr<TracedCausticsPass> create(const PluginSetup& plugin,
                                                    const ocean_scene::Model& scene,
                                                    const glm::dvec3& cameraPosition,
                                                    const reference::FrameTraceDesc& trace,
                                                    std::string& error);

  // Call right after the plugin's own pass, inside the frame.
  bool run(const HostFrame& frame, std::string& error);
  // The same into `target` (RGBA, float-readable), after the frame: the plugin's last frame
  // (its G-buffer and water texture) must still be the one rendered. The temporal-stability
  // measurement isolates the traced light this way, in a cleared target of its own.
  bool addTo(GLuint target, std::string& error);

  // After run(): the trace and the receivers it was gathered on.
  const reference::FrameTraceResult& result() const { return result_; }
  const reference::FrameReceivers& receivers() const { return receivers_; }
  size_t triangleCount() const { return scene_->triangleCount(); }

 private:
  TracedCausticsPass() = default;
  const PluginSetup* plugin_ = nullptr;
  std::unique_ptr<reference::EmbreeScene> scene_;
  glm::dvec3 sceneOrigin_{0.0};
  reference::FrameTraceDesc trace_;
  reference::FrameReceivers receivers_;
  reference::FrameTraceResult result_;
};

}  // namespace ocean
