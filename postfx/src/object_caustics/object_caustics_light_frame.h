#pragma once
// A local light's view of the casters: which casters it reaches, and the perspective
// view from it that holds them, fitted in double precision. CPU only: the frame plan decides
// from it whether the light runs, the block is built from it.
#include <postfx/postfx.h>

#include "object_caustics/object_caustics_frame.h"

namespace postfx::detail {

// Fits light `index` of frame.objectCaustics.lights into `out` (its `light`, `position`,
// `direction` = the view's axis, `casters`, depth range and frusta). Returns why the light
// makes no caustics (out is then unspecified), or LightSkip::None.
LightSkip fitLocalLightFrame(const FrameDesc& frame, int index, ObjectLightFrame& out);

}  // namespace postfx::detail
