#pragma once
// Validation of ObjectCausticsFrame's local lights (postfx/lights.h): CPU values and GL queries
// only, like every other check, so a refused frame leaves the host's GL state untouched.
#include <string>

#include <postfx/postfx.h>

namespace postfx::detail {

// lightCount against CreateDesc::maxLocalLights, then every light's fields; the message names
// the field, e.g. "objectCaustics.lights[2].coneAngleDegrees".
Result validateLocalLights(const CreateDesc& create, const ObjectCausticsFrame& frame,
                           std::string& error);

}  // namespace postfx::detail
