#pragma once
// The GLSL/C++ shared headers of the plugin, compiled as C++ in namespace postfx::shared.
#include <glm/glm.hpp>

#include "shared/common.h"  // before the namespace: it includes GLM

namespace postfx {
#include "shared/postfx_bindings.h"
#include "shared/postfx_caustics.h"
#include "shared/postfx_caustics_block.h"
#include "shared/postfx_godrays.h"
#include "shared/postfx_godrays_block.h"
#include "shared/postfx_irradiance.h"
#include "shared/postfx_object_caustics.h"
#include "shared/postfx_tile_irradiance.h"
}  // namespace postfx
