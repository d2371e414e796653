#pragma once
// Validation of Feature::ObjectCaustics inputs: CPU values and GL *queries* only (no binds, no
// state changes), so a rejected frame leaves the host's GL state untouched.
#include <string>

#include <postfx/postfx.h>

namespace postfx::detail {

Result validateObjectCaustics(const CreateDesc& create, const FrameDesc& frame, std::string& error);

// A receiver depth map (the sun's or a light's) and its projection; `field` names it in the
// message ("objectCaustics.lights[2].receivers").
Result checkReceivers(const std::string& field, const SunShadowMap& receivers, std::string& error);

}  // namespace postfx::detail
