#pragma once
// Input validation. Everything here only reads: CPU values and GL *queries* (no binds, no state
// changes, no GL errors), so a rejected call leaves the host's GL state untouched.
#include <epoxy/gl.h>

#include <string>

#include <postfx/postfx.h>

#include "frame_constants.h"

namespace postfx::detail {

Result validateCreateDesc(const CreateDesc& desc, std::string& error);

// How many water cascades the context's shaders are written for (a valid desc's).
inline int waterCascadeSlots(const CreateDesc& desc) {
  return desc.waterTexture == WaterTextureType::Single2D ? 1 : desc.maxWaterCascades;
}

// Range checks of the god-ray settings (part of validateFrameValues with Feature::GodRays).
Result validateGodRays(const GodRaySettings& settings, std::string& error);

// CPU-only checks of the frame: finite camera, sane projection, settings in range.
Result validateFrameValues(const CreateDesc& create, const FrameDesc& frame, std::string& error);

// What the texture checks learnt, for the pass.
struct ValidatedTextures {
  int width = 0, height = 0;  // of the target (= G-buffer)
  WaterTextureInfo water;
  bool waterMipmapped = false;  // mip-complete: sample with mips; otherwise level 0 only
};

// GL-query checks of every texture: a texture name, the right target and format, sizes that
// match. Runs after validateFrameValues.
// A host depth texture (GL_TEXTURE_2D, depth format, depth mode): the checks every depth input
// gets, for the object caustics' receiver map.
Result checkDepthTexture(const char* field, const TextureRef& ref, std::string& error);

Result validateFrameTextures(const CreateDesc& create, const FrameDesc& frame,
                             ValidatedTextures& out, std::string& error);

}  // namespace postfx::detail
