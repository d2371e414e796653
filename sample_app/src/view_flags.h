#pragma once
// The camera and sun a command renders from: the named preset with the command line's
// --camera-position, --camera-look-at, --fov, --sun-azimuth and --sun-elevation over it.
#include <string>

#include <postfx/settings.h>

#include "camera.h"
#include "options.h"

namespace ocean {

// False with one line when the preset is unknown or the camera cannot look at the point
// (it is the camera's own position, or straight above or below it).
bool resolveView(const Options& options, Preset& preset, std::string& error);

// `options` with the preset's caustic settings (Preset::maxReceiverDepth, tileResolution,
// causticsLookup, reflectedCaustics, reflectedGrid, reflectedMaxHeight) where the command line
// left the plugin's default.
Options withPresetCaustics(Options options, const Preset& preset);

// The same on settings already live (`view` switching presets): the preset's caustic settings,
// or the plugin's defaults where it has none, unless the command line `options` set them.
void applyPresetCaustics(const Options& options, const Preset& preset,
                         postfx::CausticsSettings& caustics);

// The yaw and pitch (radians, Camera's convention) that look along `direction`; false when it
// is shorter than 1e-6 m or within 1 degree of vertical (Camera's basis needs a horizontal
// component).
bool lookAlong(const glm::dvec3& direction, double& yaw, double& pitch);

}  // namespace ocean
