#pragma once
// Connects the postfx plugin to the sample renderer: creates the plugin context and installs
// the pass that hands it the host's textures every frame. This file is the worked example of
// an integration; the README's snippet is a condensed copy.
#include <gbuffer/codec.h>
#include <postfx/postfx.h>

#include <memory>
#include <string>
#include <vector>

#include "options.h"
#include "renderer.h"

namespace ocean {

class PluginSetup {
 public:
  // benchmarkFloor: also run the plugin's floor pass, for ratios (ocean_sample bench).
  static std::unique_ptr<PluginSetup> create(Renderer& renderer, const Options& options,
                                             bool benchmarkFloor, std::string& error);
  ~PluginSetup();
  PluginSetup(const PluginSetup&) = delete;
  PluginSetup& operator=(const PluginSetup&) = delete;

  postfx::CausticsSettings& caustics() { return caustics_; }
  postfx::GodRaySettings& godRays() { return godRays_; }
  postfx::ObjectCausticsSettings& objectCaustics() { return objectCaustics_; }
  // intensity is the physical 1/pi over the sun above the water; each frame hands the plugin
  // the factor that makes its sun (the beam below the surface) that sun (reflectedIntensity).
  postfx::ReflectedCausticsSettings& reflectedCaustics() { return reflectedCaustics_; }
  const postfx::FrameStats& stats() const { return postfx::stats(*context_); }
  // The work account's steps of the last resolved frame (Options::workAccount).
  postfx::WorkSteps workSteps() const { return postfx::workSteps(*context_); }
  // Each later dispatch's time by the CPU's clock (ms), the GL pipeline drained before and
  // after it, appended to `out` (null: not measured). For bench --work on a CPU rasteriser.
  void measureWallTime(std::vector<double>* out) { wallTimes_ = out; }
  // Several views in one dispatch (split-screen, a cube-map probe): the first frame gives what
  // they share (sun, water, casters, the receiver maps), each frame its camera, G-buffer, target
  // and sun shadow map. The plugin's views are made on first use, one per position in the list.
  bool dispatchViews(const std::vector<HostFrame>& frames, std::string& error);
  // View i's own passes (dispatchViews); stats() has the shared ones.
  const postfx::FrameStats& viewStats(int i) const { return postfx::stats(*views_[size_t(i)]); }
  std::string timingSummary() const;  // "caustics 0.41 ms (median)" ...
  // What the last dispatch was given, for tools that re-dispatch the same frame with other
  // settings (ocean_sample report). Its textures stay valid until the next render.
  const postfx::CreateDesc& createDesc() const { return createDesc_; }
  const postfx::FrameDesc& lastFrame() const { return lastFrame_; }

 private:
  PluginSetup() = default;
  bool dispatch(const HostFrame& frame, std::string& error);
  // The plugin's frame for `frame` (the casters' and lights' arrays live in this object).
  postfx::FrameDesc describe(const HostFrame& frame);
  // The reflected caustics' intensity for the plugin this frame: reflectedCaustics_.intensity
  // over the surface's transmission of the frame's sun, 0 without a sun.
  float reflectedIntensity(const HostFrame& frame) const;

  postfx::Context* context_ = nullptr;
  postfx::CreateDesc createDesc_;
  postfx::FrameDesc lastFrame_;
  postfx::CausticsSettings caustics_;
  postfx::GodRaySettings godRays_;
  postfx::ObjectCausticsSettings objectCaustics_;
  postfx::ReflectedCausticsSettings reflectedCaustics_;
  std::vector<postfx::CasterMesh> casters_;  // rebuilt each frame, kept for its capacity
  std::vector<postfx::LocalLight> lights_;   // likewise
  std::vector<postfx::View*> views_;         // dispatchViews', freed with the context
  // --flat-local-water: the regions given with a flat surface of their own (one zero texel,
  // clamped over the whole rectangle).
  bool flatLocalWater_ = false;
  int localWaterGrid_ = 0;  // --local-water-grid (0: the scene's)
  GLuint flatSurface_ = 0;
  // --flat-water: the sea given flat (one zero texel per cascade layer, RG32F array).
  bool flatWater_ = false;
  GLuint flatWaterTexture_ = 0;
  std::vector<postfx::LocalWater> regions_;  // the scene's, changed by those two options
  std::vector<double>* wallTimes_ = nullptr;
};

}  // namespace ocean
