#include "view_flags.h"

#include <cmath>

namespace ocean {

bool lookAlong(const glm::dvec3& direction, double& yaw, double& pitch) {
  const double length = glm::length(direction);
  if (!(length > 1e-6)) return false;
  const glm::dvec3 d = direction / length;
  // Camera::rotation() crosses the world up with the view direction: within a degree of
  // vertical the image would spin with the last bits of x and z.
  if (std::abs(d.y) > std::cos(glm::radians(1.0))) return false;
  pitch = std::asin(d.y);
  yaw = std::atan2(-d.x, -d.z);  // Camera::forward(): (-sin yaw cos pitch, ., -cos yaw cos pitch)
  return true;
}

Options withPresetCaustics(Options options, const Preset& preset) {
  if (options.maxReceiverDepth <= 0.0) options.maxReceiverDepth = preset.maxReceiverDepth;
  if (options.tileResolution <= 0) options.tileResolution = preset.tileResolution;
  if (options.causticsLookup <= 0) options.causticsLookup = preset.causticsLookup;
  if (!options.reflectedCaustics) options.reflectedCaustics = preset.reflectedCaustics;
  if (options.reflectedGrid <= 0) options.reflectedGrid = preset.reflectedGrid;
  if (options.reflectedMaxHeight <= 0.0) options.reflectedMaxHeight = preset.reflectedMaxHeight;
  return options;
}

void applyPresetCaustics(const Options& options, const Preset& preset,
                         postfx::CausticsSettings& caustics) {
  const Options chosen = withPresetCaustics(options, preset);
  const postfx::CausticsSettings defaults;
  caustics.maxReceiverDepth =
      chosen.maxReceiverDepth > 0.0 ? float(chosen.maxReceiverDepth) : defaults.maxReceiverDepth;
  caustics.tileResolution =
      chosen.tileResolution > 0 ? chosen.tileResolution : defaults.tileResolution;
  caustics.tileLookupResolution =
      chosen.causticsLookup > 0
          ? static_cast<postfx::CausticsLookupResolution>(chosen.causticsLookup)
          : defaults.tileLookupResolution;
}

bool resolveView(const Options& options, Preset& preset, std::string& error) {
  std::string known;
  if (!findPreset(options.preset, preset, known)) {
    error = "unknown preset '" + options.preset + "' (known: " + known + ")";
    return false;
  }
  if (preset.lights.size() + options.lights.size() > size_t(kMaxSceneLights)) {
    error = "--light: the preset has " + std::to_string(preset.lights.size()) +
            " light(s); with --light at most " + std::to_string(kMaxSceneLights) + " in all";
    return false;
  }
  preset.lights.insert(preset.lights.end(), options.lights.begin(), options.lights.end());
  Camera& camera = preset.camera;
  if (options.cameraPosition) camera.position = *options.cameraPosition;
  if (options.cameraLookAt &&
      !lookAlong(*options.cameraLookAt - camera.position, camera.yaw, camera.pitch)) {
    error =
        "--camera-look-at must differ from the camera position and not be straight above or "
        "below it";
    return false;
  }
  if (options.fovDegrees) camera.fovY = glm::radians(*options.fovDegrees);
  if (options.sunAzimuthDegrees) preset.sun.azimuth = glm::radians(*options.sunAzimuthDegrees);
  if (options.sunElevationDegrees)
    preset.sun.elevation = glm::radians(*options.sunElevationDegrees);
  if (options.exposureStops) preset.exposureStops = *options.exposureStops;
  return true;
}

}  // namespace ocean
