#pragma once
// The GLSL/C++ shared headers of the plugin, compiled as C++ in namespace postfx::shared.
#include <glm/glm.hpp>

#include "shared/common.h"  // before the namespace: it includes GLM

namespace postfx {
#include "postfx/common/postfx_bindings.h"
#include "postfx/god_rays/postfx_godrays.h"
#include "postfx/god_rays/postfx_godrays_block.h"
#include "postfx/object_caustics/postfx_object_caustics.h"
#include "postfx/reflected_caustics/postfx_reflected_caustics.h"
#include "postfx/seabed_caustics/postfx_caustics.h"
#include "postfx/seabed_caustics/postfx_caustics_block.h"
#include "postfx/seabed_caustics/postfx_local_water.h"
#include "postfx/seabed_caustics/postfx_tile_irradiance.h"
#include "postfx/seabed_caustics/postfx_wavefront_area_ratio.h"
}  // namespace postfx
