#pragma once
// The sample's camera: world position in double (the plugin's convention), orientation as yaw
// and pitch, reverse-Z infinite perspective (the recommended host setup).
#include <glm/glm.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "scene_kind.h"
#include "scene_light.h"

namespace ocean {

struct Camera {
  glm::dvec3 position{0.0, -4.0, 12.0};  // metres, y up, water level y = 0
  double yaw = 0.0;                      // radians, 0 looks toward -Z
  double pitch = 0.0;                    // radians, positive looks up
  double fovY = glm::radians(60.0);      // radians
  double nearPlane = 0.05;               // metres

  glm::dvec3 forward() const;
  glm::dmat3 rotation() const;                 // camera-to-world
  glm::mat4 viewRotation() const;              // world-to-camera, translation removed
  glm::dmat4 projection(double aspect) const;  // reverse-Z, infinite far, column-major
};

struct Sun {
  double elevation = glm::radians(55.0);   // radians above the horizon
  double azimuth = glm::radians(200.0);    // radians, 0 = toward -Z, clockwise seen from above
  glm::vec3 irradiance{3.2f, 3.0f, 2.7f};  // linear RGB at normal incidence above the water
  glm::dvec3 direction() const;            // unit vector toward the sun
};

struct Preset {
  std::string_view name;
  std::string_view description;
  Camera camera;
  Sun sun;
  std::vector<SceneLight> lights;  // point and spot lights (--light adds to them)
  // Exposure in stops (EV) before the tone curve, as a photographer sets it for the scene's
  // light: the physically lit water below the surface is ~1/4 as bright as sunlit sand
  // above it. --exposure replaces it.
  double exposureStops = 0.0;
  // Wind over the sea, m/s at 10 m (postfx::water::OceanDesc::windSpeed): the sea state the
  // preset is lit through. 10 is a fresh breeze; the shallow reef's 4 is a calm sea, whose
  // traced light at 3 m is a crisp network.
  double windSpeed = 10.0;
  // The plugin's caustic settings the view is shown with, each 0 for the plugin's default (the
  // command line's --max-receiver-depth, --tile-resolution and --caustics-lookup win): the
  // deepest receiver the view's irradiance layers must span (m below the level), and the tile
  // grid and lookup resolution its pattern needs. The shallow reef's crisp pattern at 3 m needs
  // layers over 5 m, 512 texels a tile and full-resolution lookups (docs/measurements.md,
  // "Shallow preset"); the 10 m presets are right at the defaults.
  double maxReceiverDepth = 0.0;
  int tileResolution = 0;
  int causticsLookup = 0;  // 1 full, 2 half
  // The world it is shown in: the sea (every preset but one) or the pool on land, whose water
  // is a ripple simulation handed to the plugin as a local water region.
  SceneKind scene = SceneKind::Sea;
  // The plugin's reflected caustics above the water (Feature::ReflectedCaustics), on where the
  // view has receivers above the level facing the water (--reflected-caustics and
  // --no-reflected-caustics win); their water grid cells per side (--reflected-grid wins) and
  // the height of their highest layer (m above the level), each 0 for the plugin's default
  // (ReflectedCausticsSettings::gridResolution, maxHeight).
  bool reflectedCaustics = false;
  int reflectedGrid = 0;
  double reflectedMaxHeight = 0.0;
  // The sun's shadows above the level cast along the sun in air (RenderSettings::airShadows):
  // the harbour's, whose structures stand in the water. The others keep the refracted sun's map
  // as they were drawn (their frames unchanged), though the pool's deck and the wake's ball
  // stand above the level too.
  bool airShadows = false;
};

// Returns false when the name is unknown; `known` lists the valid names for the message.
bool findPreset(std::string_view name, Preset& preset, std::string& known);

}  // namespace ocean
