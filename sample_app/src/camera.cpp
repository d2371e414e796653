#include "camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <array>

#include <scene/harbour_scene.h>
#include <scene/scene_features.h>
#include <scene/seabed.h>

namespace ocean {

glm::dvec3 Camera::forward() const {
  return {-std::sin(yaw) * std::cos(pitch), std::sin(pitch), -std::cos(yaw) * std::cos(pitch)};
}

glm::dmat3 Camera::rotation() const {
  const glm::dvec3 back = -forward();
  const glm::dvec3 right = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), back));
  const glm::dvec3 up = glm::cross(back, right);
  return glm::dmat3(right, up, back);
}

glm::mat4 Camera::viewRotation() const {
  return glm::mat4(glm::transpose(rotation()));
}

glm::dmat4 Camera::projection(double aspect) const {
  const double f = 1.0 / std::tan(fovY * 0.5);
  glm::dmat4 p(0.0);
  p[0][0] = f / aspect;
  p[1][1] = f;
  p[2][3] = -1.0;
  p[3][2] = nearPlane;  // reverse-Z, infinite far: depth = near / -z_view
  return p;
}

glm::dvec3 Sun::direction() const {
  return {-std::sin(azimuth) * std::cos(elevation), std::sin(elevation),
          -std::cos(azimuth) * std::cos(elevation)};
}

namespace {

Preset makePreset(std::string_view name, std::string_view description, glm::dvec3 position,
                  double yawDegrees, double pitchDegrees, double sunElevationDegrees,
                  double sunAzimuthDegrees) {
  Preset preset{name, description, {}, {}, {}, 0.0};
  preset.camera.position = position;
  preset.camera.yaw = glm::radians(yawDegrees);
  preset.camera.pitch = glm::radians(pitchDegrees);
  preset.sun.elevation = glm::radians(sunElevationDegrees);
  preset.sun.azimuth = glm::radians(sunAzimuthDegrees);
  return preset;
}

// A night dive: a diver's torch above and behind the glass sphere, shining
// through it onto the sand, the camera beside them. The sun is below the horizon (no sunlight,
// no sun caustics): the torch carries the scene, over the sky's faint ambient.
Preset torchPreset() {
  const glm::dvec2 xz = ocean_scene::features::kGlassSphereXZ;
  const double sand = ocean_scene::seabedHeight(xz.x, xz.y);
  const glm::dvec3 sphere(xz.x, sand + ocean_scene::features::kGlassSphereHeightAboveSand, xz.y);
  Preset preset =
      makePreset("torch",
                 "underwater at night, a diver's torch shining through the glass sphere "
                 "onto the sand",
                 sphere + glm::dvec3(3.6, 0.9, 4.2), 0.0, 0.0, -12.0, 40.0);
  preset.camera.fovY = glm::radians(55.0);
  SceneLight torch;
  torch.type = SceneLight::Type::Spot;
  torch.position = sphere + glm::dvec3(-1.5, 2.2, -1.1);  // 2.9 m from the centre
  // Through the sphere's centre: its caustic lands in the middle of its shadow on the sand.
  torch.direction = glm::normalize(sphere - torch.position);
  torch.intensity = glm::vec3(150.0f, 140.0f, 120.0f);  // a warm LED: 18 at 2.9 m
  torch.coneAngleDegrees = 55.0f;
  torch.coneSoftness = 0.35f;
  torch.range = 20.0;
  preset.lights.push_back(torch);
  // Look between the sphere and its shadow on the sand, where the beam meets it.
  const double toSand = (sphere.y - sand) / -torch.direction.y;
  const glm::dvec3 target = sphere + torch.direction * (0.6 * toSand);
  const glm::dvec3 view = glm::normalize(target - preset.camera.position);
  preset.camera.pitch = std::asin(view.y);
  preset.camera.yaw = std::atan2(-view.x, -view.z);
  return preset;
}

// The hero view: a calm, clear morning over the sandbank's reef (scene_features.h), 3 m of
// water over sand, the sun high and ahead-right: the glass sphere's focus on the sand below
// it, the brass ring's cardioid, god rays from the same surface.
Preset shallowPreset() {
  using namespace ocean_scene::features;
  const double sand = ocean_scene::seabedHeight(kShallowSphereXZ.x, kShallowSphereXZ.y);
  const glm::dvec3 sphere(kShallowSphereXZ.x, sand + kShallowSphereHeightAboveSand,
                          kShallowSphereXZ.y);
  Preset preset = makePreset("shallow",
                             "a calm sea over a sandbank reef 3 m deep: the glass sphere's focus, "
                             "the ring's cardioid",
                             glm::dvec3(kShallowSphereXZ.x + 0.9, -0.8, kShallowSphereXZ.y + 4.6),
                             0.0, 0.0, 66.0, -35.0);
  preset.windSpeed = 4.0;
  // Sand 2.5-4.5 m deep, rocks to 5 m; see Preset::maxReceiverDepth.
  preset.maxReceiverDepth = 5.0;
  preset.tileResolution = 512;
  preset.causticsLookup = 1;
  // Aim between the sphere and the sand under it, where its caustic lands.
  const glm::dvec3 target(sphere.x, 0.5 * (sphere.y + sand), sphere.z);
  const glm::dvec3 view = glm::normalize(target - preset.camera.position);
  preset.camera.pitch = std::asin(view.y);
  preset.camera.yaw = std::atan2(-view.x, -view.z);
  return preset;
}

// The pool, after webgl-water: from above the deck at an angle, the sun high to the right so the
// ball's shadow falls across the floor toward the camera. The deck hides the horizon.
Preset poolPreset() {
  Preset preset = makePreset("pool",
                             "a tiled pool on land after webgl-water: ripples from drops and a "
                             "moving ball, their caustics on the floor and walls",
                             glm::dvec3(0.0, 0.0, 0.0), 0.0, 0.0, 52.0, -60.0);
  preset.scene = SceneKind::Pool;
  preset.camera.fovY = glm::radians(50.0);
  // 11 m from a point 0.6 m below the water at the pool's centre, 45 degrees down.
  const glm::dvec3 target(0.0, -0.6, 0.0);
  const double pitch = glm::radians(-45.0), yaw = glm::radians(-20.0);
  preset.camera.pitch = pitch;
  preset.camera.yaw = yaw;
  preset.camera.position = target - 11.0 * preset.camera.forward();
  // The pool's water is its own (a local water region); the sea is not drawn and its state
  // does not matter: a calm one costs the same.
  preset.windSpeed = 4.0;
  // The floor 2 m down: the plugin's periodic layers need not go deeper.
  preset.maxReceiverDepth = 2.5;
  return preset;
}

// Open sea from above: a ball towed in a circle (wake_water.h) leaves a wake on a calm sea, the
// sun ahead and high enough to light the water under it.
Preset wakePreset() {
  Preset preset = makePreset("wake",
                             "a ball towed across a calm sea, its simulated wake added to the "
                             "sea's surface (an Add local water region following it)",
                             glm::dvec3(0.0, 0.0, 0.0), 0.0, 0.0, 45.0, 160.0);
  preset.scene = SceneKind::Wake;
  // 17 m from the circle's centre (wake_water.h: (0, 4), 8 m across), 32 degrees down.
  const glm::dvec3 target(0.0, 0.0, 4.0);
  preset.camera.pitch = glm::radians(-32.0);
  preset.camera.yaw = 0.0;
  preset.camera.position = target - 17.0 * preset.camera.forward();
  preset.windSpeed = 4.0;
  return preset;
}

// A calm harbour in the low sun of a late afternoon, seen from a dinghy 0.65 m above the water:
// the waves' reflected light on the pier's underside (which nothing else lights), on the quay's
// wall in the pier's shade and in the sun, and on the moored boat's side, a network moving
// upward and away from the sun. The sun is behind the camera and to its right (azimuth 215
// degrees, 20 up: R = 0.13 of it mirrored), so the wall and the hull's side face it and the
// pier's sunward side is toward the camera; the water that lights the underside (3.5 m sunward
// of it) lies beside the pier and under its sunward half, outside its shade. Every point in
// view of the underside, the boat's side and the wall between them is lit from water within 8 m
// of the camera along x and z, inside the plugin's 24 m window short of its outer eighth, where
// the pattern fades (farther along the quay the wall takes the flat mean).
Preset harbourPreset() {
  Preset preset = makePreset("harbour",
                             "a calm harbour in a low sun: the waves' reflected light on the "
                             "underside of a pier, a quay wall and a moored boat's side",
                             glm::dvec3(0.0), 0.0, 0.0, 20.0, 215.0);
  preset.scene = SceneKind::Harbour;
  const ocean_scene::HarbourSceneParams harbour;
  const glm::dvec3 origin(harbour.origin.x, 0.0, harbour.origin.y);
  preset.camera.position = origin + glm::dvec3(5.0, 0.65, 8.0);
  preset.camera.fovY = glm::radians(58.0);
  // Toward the pier's root at the quay, level with its deck: its underside on the left, the
  // wall ahead, the boat on the right.
  const glm::dvec3 target = origin + glm::dvec3(0.0, 1.45, 0.0);
  const glm::dvec3 view = glm::normalize(target - preset.camera.position);
  preset.camera.pitch = std::asin(view.y);
  preset.camera.yaw = std::atan2(-view.x, -view.z);
  // A light air (3 m/s): a calm harbour, whose reflected network stays legible a metre or two
  // up instead of spreading into the mean.
  preset.windSpeed = 3.0;
  preset.reflectedCaustics = true;
  // A mirror deviates light by twice the slope: the network a metre up is drawn by ripples a
  // few centimetres long, which the plugin's default grid (512 over 24 m, 4.7 cm) low-passes
  // away; 2048 (1.2 cm) keeps them, and lands enough rays on the pier's underside, beyond the
  // ripples' focus, for its light to settle (docs/measurements.md, "Reflected caustics").
  preset.reflectedGrid = 2048;
  // The highest receiver facing the water is the quay's wall, to 2.4 m: rays followed (and the
  // height layers, with ReflectedLanding::HeightLayers) to 2.5 m.
  preset.reflectedMaxHeight = 2.5;
  // The pier shades the water beside it, the boat the wall, along the sun in air.
  preset.airShadows = true;
  return preset;
}

Preset exposed(Preset preset, double stops) {
  preset.exposureStops = stops;
  return preset;
}

// Exposures chosen by eye at 1280x720 for each view's light: the seabed at 10 m gets ~1/4 of
// the sun above it (absorption, 1 - Fresnel, Lambert's 1/pi at an oblique sun), looking up
// meets Snell's window, and from above the sky dominates.
const std::array<Preset, 9>& presets() {
  static const std::array<Preset, 9> all = {
      exposed(makePreset("seabed", "underwater, looking down at the seabed, pillar and arch",
                         {2.0, -4.5, 14.0}, 8.0, -22.0, 62.0, 200.0),
              1.5),
      exposed(makePreset("sunward", "underwater, looking up toward the sun through Snell's window",
                         {0.0, -7.0, 6.0}, 200.0, 38.0, 62.0, 200.0),
              1.0),
      exposed(makePreset("above", "above the water, looking down into it", {0.0, 6.0, 22.0}, 0.0,
                         -28.0, 48.0, 150.0),
              0.5),
      exposed(makePreset("waterline", "camera 3 cm above the mean water plane, half in, half out",
                         {0.0, 0.03, 16.0}, 5.0, -4.0, 40.0, 170.0),
              0.5),
      exposed(torchPreset(), 0.5),
      exposed(shallowPreset(), 0.5),
      exposed(poolPreset(), 0.0),
      exposed(wakePreset(), 0.5),
      exposed(harbourPreset(), 0.25),
  };
  return all;
}

}  // namespace

bool findPreset(std::string_view name, Preset& preset, std::string& known) {
  known.clear();
  for (const Preset& candidate : presets()) {
    if (candidate.name == name) {
      preset = candidate;
      return true;
    }
    known += (known.empty() ? "" : ", ") + std::string(candidate.name);
  }
  return false;
}

}  // namespace ocean
