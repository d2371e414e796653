#pragma once
// The local water regions' checks (postfx/local_water.h): their values with the frame's
// (validateFrameValues), their textures with the frame's textures (validateFrameTextures).
#include <string>

#include "core/validation.h"

namespace postfx::detail {

// CPU only: count, Feature::LocalWater, and every field of every region in range.
Result validateLocalWaterValues(const CreateDesc& create, const WaterSurface& water,
                                std::string& error);
// GL queries only: each region's texture a GL_TEXTURE_2D in one of the cascades' formats.
Result validateLocalWaterTextures(const WaterSurface& water, std::string& error);

}  // namespace postfx::detail
