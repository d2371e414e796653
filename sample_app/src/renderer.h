#pragma once
// The sample host: a small deferred renderer of the ocean scene. Per frame: ocean update, local
// water update (a pool's or a wake's simulation, local_water_source.h), sun shadow map,
// G-buffer (without glass), deferred lighting into RGBA16F, underwater fog, [the plugin's
// passes], metal and glass drawn forward (caster_surfaces.h), the water surface (the sea's, with
// a local region on it or instead of it), tone mapping into RGBA8.
#include <epoxy/gl.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <gbuffer/targets.h>
#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/water/ocean.h>
#include <postfx/water/optics.h>
#include <scene/model.h>

#include "camera.h"
#include "caster_surfaces.h"
#include "gpu_scene.h"
#include "light_shadow_maps.h"
#include "local_water_source.h"
#include "shadow_map.h"
#include "water_grid.h"

namespace ocean {

struct RenderSettings {
  int width = 1280, height = 720;  // pixels
  int waterResolution = 256;       // FFT texels per cascade side (power of two, 8..512)
  int shadowMapSize = 2048;        // texels per side
  int lightMapSize = 1024;         // texels per side of each point/spot light's depth maps
  double shadowRadius = 40.0;      // metres around the camera the shadow map covers
  float exposure = 1.0f;
  double windSpeed = 10.0;  // m/s at 10 m height: the sea state (OceanDesc::windSpeed)
  // The sun's shadow map is drawn along the refracted sun, right for everything under the water
  // (the plugin masks its caustics with it). On: points above the level are moved along the sun
  // in air onto it (shaders/sample/shadow_space.glsl), so that structures standing in the water
  // shade each other, the water and the seabed as the sun does (the harbour; its meshes are
  // split at the level). Off: above the level too the map is the refracted sun's, as the sea's
  // presets have always been drawn.
  bool airShadows = false;
};

struct FrameInput {
  Camera camera;
  Sun sun;
  double timeSeconds = 0.0;
};

// A point or spot light as the plugin sees it: the light, and its receiver map (the view from
// the light without the caustic casters; 0 without enableReceiverMap()).
struct HostLight {
  SceneLight light;
  glm::dmat4 worldToClip{1.0};  // of its depth maps: world -> light clip, forward [0,1] depth
  GLuint receiverMap = 0;
};

// What a plugin pass sees of the host's frame (the host owns all of it).
struct HostFrame {
  const gbuffer::Targets& targets;
  GLuint target;  // the fogged HDR buffer (RGBA16F) the plugin adds into
  const FrameInput& input;
  const postfx::water::Ocean& ocean;
  const postfx::water::Optics& optics;
  GLuint shadowMap;              // D32F, forward [0,1], compare mode on
  glm::dmat4 shadowWorldToClip;  // world -> shadow clip, double, translation included
  glm::dmat4 projection;         // reverse-Z infinite
  // With enableReceiverMap(): the shadow map again without the caustic casters (same matrix),
  // the receivers of the plugin's object caustics; 0 otherwise.
  GLuint receiverMap;
  const std::vector<CasterInstance>& casters;
  const std::vector<HostLight>& lights;
  // The local water regions (a pool's, a wake's) for the plugin; empty without local water.
  const std::vector<postfx::LocalWater>& localWater;
};
// Called after lighting and fog, before the water surface; returns false with a message to fail
// the frame.
using PluginPass = std::function<bool(const HostFrame&, std::string& error)>;

class Renderer {
 public:
  static std::unique_ptr<Renderer> create(const RenderSettings& settings,
                                          const ocean_scene::Model& scene, std::string& error);
  // Another view of `primary`'s world (split-screen, a probe face): its own targets, shadow
  // maps and scene buffers, `primary`'s ocean, which only the primary updates (render the
  // primary's frame first). The primary must outlive it.
  static std::unique_ptr<Renderer> createView(const RenderSettings& settings,
                                              const ocean_scene::Model& scene, Renderer& primary,
                                              std::string& error);
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  void setPluginPass(PluginPass pass) { plugin_ = std::move(pass); }
  const PluginPass& pluginPass() const { return plugin_; }
  // Also render the receiver map each frame (for the plugin's object caustics).
  void enableReceiverMap();
  // Local water animated with the frame's time (a pool, a wake): updated at each beginFrame
  // (by the primary only; views share it), its regions drawn by the surface pass and handed to
  // the plugin, the instances it moves moved. Set before the plugin is created (PluginSetup
  // asks for Feature::LocalWater when there is some). nullptr: none.
  void setLocalWater(std::shared_ptr<LocalWaterSource> source) { localWater_ = std::move(source); }
  LocalWaterSource* localWater() const { return localWater_.get(); }
  // The scene's point and spot lights (at most kMaxSceneLights): lit with a shadow map each.
  void setLights(const std::vector<SceneLight>& lights);
  const std::vector<HostLight>& lights() const { return hostLights_; }
  bool render(const FrameInput& input, std::string& error);
  // render() in three steps, for hosts that hand the plugin several views at once: everything
  // before the plugin (ocean, shadow maps, G-buffer, lighting, fog), what the plugin sees of it
  // (valid until the next beginFrame), and everything after (casters, water surface, tone map).
  bool beginFrame(const FrameInput& input, std::string& error);
  HostFrame hostFrame() const;
  void endFrame();

  // Blits the tone-mapped image into a host framebuffer (the window's is 0).
  void presentTo(GLuint framebuffer, int width, int height) const;
  std::vector<uint8_t> readColor() const;   // RGBA8 sRGB, bottom row first (GL order)
  std::vector<float> readRadiance() const;  // RGBA32F linear, after fog and water surface
  const RenderSettings& settings() const { return settings_; }
  const gbuffer::Targets& targets() const { return targets_; }
  const postfx::water::Optics& optics() const { return optics_; }
  // Read at every render: the view edits it live.
  postfx::water::Optics& optics() { return optics_; }
  postfx::water::Ocean& ocean() { return *ocean_; }

 private:
  Renderer() = default;
  bool initialise(const ocean_scene::Model& scene, std::string& error);
  // Uploads the frame constants; returns the camera projection it derived them from.
  glm::dmat4 updateFrameConstants(const FrameInput& input);
  void updateLightConstants(const glm::dvec3& eye);
  void drawLightMaps(const glm::dvec3& eye);
  // The water surface's local water uniforms (none without regions) for the sea's grid or the
  // first region's own square.
  void setLocalWaterUniforms(const glm::dvec3& eye, bool regionSquare);

  RenderSettings settings_;
  postfx::water::Optics optics_;
  gbuffer::Targets targets_;
  std::shared_ptr<postfx::water::Ocean> ocean_;
  bool updatesOcean_ = true;  // false for a view of another renderer's ocean
  FrameInput input_;          // beginFrame's
  glm::dmat4 projection_{1.0};
  GpuScene scene_;
  ShadowMap shadowMap_;
  ShadowMap receiverMap_;  // created by enableReceiverMap()
  std::vector<std::unique_ptr<LightDepthMaps>> lightMaps_;
  std::vector<HostLight> hostLights_;
  WaterGrid waterGrid_;
  WaterGrid regionGrid_;  // a local water region's square (created with setLocalWater's first use)
  std::shared_ptr<LocalWaterSource> localWater_;
  std::vector<postfx::LocalWater> noLocalWater_;  // what hostFrame() hands without any
  glkit::Program geometry_, shadow_, lightShadow_, lighting_, composite_, water_, tonemap_;
  glkit::Buffer frameUniforms_, lightUniforms_;
  glkit::VertexArray emptyVao_;
  glkit::Texture fogged_;  // RGBA16F: the frame after fog, plus the water surface
  glkit::Framebuffer foggedFbo_;
  CasterSurfaces casterSurfaces_;
  // With glass: the G-buffer's depth plus the glass, which the surface pass then tests against
  // (the G-buffer itself stays as the plugin and the references read it), and the frame on it.
  glkit::Texture displayDepth_;
  glkit::Framebuffer displayFbo_;
  glkit::Texture sceneBelow_;  // RGBA16F copy of the fogged frame the surface refracts
  glkit::Texture output_;      // RGBA8 tone-mapped image
  glkit::Framebuffer outputFbo_;
  glm::dmat4 shadowWorldToClip_{1.0};
  PluginPass plugin_;
};

}  // namespace ocean
