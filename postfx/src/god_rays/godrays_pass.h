#pragma once
// The god-ray pass: a full-screen march blended additively (ONE, ONE) into the host target, or
// at half or quarter resolution into a plugin-owned GL_RG32UI texture (the light and the
// pixel's distance as four packed halves) followed by a depth-aware upsample that adds into
// the target. Runs under the state CausticsPass::bindState set (units, samplers, caustics
// block, blend); adds its own block, framebuffers and the reduced march's unit
// (POSTFX_UNIT_GODRAYS_REDUCED).
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/shared_math.h"
#include "core/work_account.h"

namespace postfx::detail {

struct ValidatedTextures;
struct SeabedInputs;

// What one view (postfx/views.h) owns of the god-ray pass: its reduced-resolution march texture
// (GodRaySettings::resolution below Full, its viewport's size divided, allocated on first use).
struct GodRaysViewTextures {
  glkit::Texture reduced;
  glkit::Framebuffer reducedFramebuffer;
  int reducedWidth = 0, reducedHeight = 0;
  std::uint64_t allocatedBytes() const {
    return std::uint64_t(reducedWidth) * std::uint64_t(reducedHeight) * 8;  // RG32UI
  }
};

class GodRaysPass {
 public:
  // Builds the programs (with the caustics pass's #defines) and GL objects (DSA: binds nothing).
  Result init(const std::string& defines, std::string& error);
  // The march that reads the tile irradiance (the seabed caustics' light) for `groups` RGBA
  // fetches per cascade and the cascades in `cascadeMask`, as CausticsPass::ensureTileProgram:
  // the TileIrradiance model's, or with `physical` the WavefrontAreaRatio window's continued by
  // the tile beyond it (as the seabed is). Built the first time a frame needs it; returns its
  // index for draw (>= 1).
  Result ensureTileProgram(int groups, int cascadeMask, bool physical, int& variant,
                           std::string& error);

  // Attaches the host target, sizes the view's reduced-resolution texture when used, uploads the
  // block; `view` and the rectangle are drawn with until the next prepare.
  Result prepare(const FrameDesc& frame, const ValidatedTextures& textures,
                 const shared::GodRaysBlock& block, GodRaysViewTextures& view, std::string& error);
  // tileVariant: 0 for the RayDeviation march, else ensureTileProgram's. `inputs`: what the
  // caustics pass's state bound (for the work account).
  void draw(const FrameDesc& frame, int tileVariant, const SeabedInputs& inputs);
  void finish();  // lets go of the host's texture

 private:
  void ensureReduced(int width, int height, GodRaysViewTextures& view);
  StageWork marchWork(const FrameDesc& frame, int tileVariant, const SeabedInputs& in) const;

  std::string defines_;
  glkit::Program full_, reduced_, upsample_;
  // Tile-field marches, full and reduced: [physical][groups - 1][cascade mask].
  static constexpr int kTileMasks = 1 << kMaxCascades;
  static constexpr int kTileVariants = 2 * kTileMasks;
  glkit::Program tileFull_[2 * kTileVariants], tileReduced_[2 * kTileVariants];
  glkit::Framebuffer framebuffer_;
  glkit::Buffer uniformBuffer_;
  glkit::Sampler reducedSampler_;
  GodRaysViewTextures* view_ = nullptr;  // the view prepare() set up
  int viewport_[4] = {0, 0, 0, 0};       // its rectangle in the target: x, y, width, height
};

}  // namespace postfx::detail
