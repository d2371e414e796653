#include "camera.h"

#include <glm/gtc/matrix_transform.hpp>

#include <array>

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
  Preset preset{name, description, {}, {}};
  preset.camera.position = position;
  preset.camera.yaw = glm::radians(yawDegrees);
  preset.camera.pitch = glm::radians(pitchDegrees);
  preset.sun.elevation = glm::radians(sunElevationDegrees);
  preset.sun.azimuth = glm::radians(sunAzimuthDegrees);
  return preset;
}

const std::array<Preset, 4>& presets() {
  static const std::array<Preset, 4> all = {
      makePreset("seabed", "underwater, looking down at the seabed, pillar and arch",
                 {2.0, -4.5, 14.0}, 8.0, -22.0, 62.0, 200.0),
      makePreset("sunward", "underwater, looking up toward the sun through Snell's window",
                 {0.0, -7.0, 6.0}, 200.0, 38.0, 62.0, 200.0),
      makePreset("above", "above the water, looking down into it", {0.0, 6.0, 22.0}, 0.0, -28.0,
                 48.0, 150.0),
      makePreset("waterline", "camera 3 cm above the mean water plane, half in, half out",
                 {0.0, 0.03, 16.0}, 5.0, -4.0, 40.0, 170.0),
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
