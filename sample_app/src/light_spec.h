#pragma once
// The --light argument:
//   point:X,Y,Z:I[:RANGE]
//   spot:X,Y,Z:DX,DY,DZ:I:CONE[:SOFTNESS[:RANGE]]
// X,Y,Z in metres (y up, water at y = 0); DX,DY,DZ the spot's axis (any length > 0); I the
// intensity (one number or R,G,B: the irradiance at 1 m, in the sample's HDR units); CONE the
// full apex angle in degrees, (0, 180); SOFTNESS the share of the half-angle faded at the edge,
// [0, 1] (default 0.3); RANGE in metres, [0, 1e6] (default 20).
#include <string>
#include <string_view>

#include "scene_light.h"

namespace ocean {

// False with a one-line reason naming the field.
bool parseLightSpec(std::string_view text, SceneLight& out, std::string& error);

}  // namespace ocean
