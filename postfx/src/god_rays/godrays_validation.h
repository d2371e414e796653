#pragma once
// The god rays' settings checks (part of validateFrameValues with Feature::GodRays).
#include <string>

#include "core/validation.h"

namespace postfx::detail {

Result validateGodRays(const GodRaySettings& settings, std::string& error);

}  // namespace postfx::detail
