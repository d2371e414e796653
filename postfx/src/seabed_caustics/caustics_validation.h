#pragma once
// The seabed caustics' settings checks (part of validateFrameValues): every field of every
// model in range, and WavefrontAreaRatio only where Feature::WavefrontAreaRatio was created.
#include <string>

#include "core/validation.h"

namespace postfx::detail {

Result validateCausticsSettings(const CreateDesc& create, const CausticsSettings& settings,
                                std::string& error);

}  // namespace postfx::detail
