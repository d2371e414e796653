#pragma once
// The caustics pass and its benchmark floor: a full-screen triangle per pass, blended
// additively (ONE, ONE) into the host's HDR target through a framebuffer of our own, with the
// raw caustic factor as a second, unblended attachment when enabled.
// A fragment pass rather than compute: the additive blend is free in the ROPs on real GPUs,
// works for every target format (R11G11B10F has no atomic/image read-modify-write), and sky or
// above-water pixels leave with a discard.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/shared_math.h"
#include "core/validation.h"
#include "core/work_account.h"

namespace postfx::detail {

// What one view (postfx/views.h) owns of the caustics pass: its raw output (RawCausticOutput,
// the size of its target) and its half-resolution lookups (CausticsLookupResolution::Half, the
// size of half its viewport, allocated on first use). Kept per view so that views of different
// sizes never reallocate each other's every frame; freed with the view.
struct CausticsViewTextures {
  glkit::Texture raw;
  int rawWidth = 0, rawHeight = 0;
  glkit::Texture reduced;
  glkit::Framebuffer reducedFramebuffer;
  int reducedWidth = 0, reducedHeight = 0;
  std::uint64_t allocatedBytes() const;
};

// The #defines of the context's features and conventions, for every postfx program.
std::string shaderDefines(const CreateDesc& desc);

// What CausticsPass::bindState bound for the passes under its state, for the work account.
struct SeabedInputs {
  GLuint depth = 0, normal = 0, albedo = 0, water = 0, shadow = 0, irradiance = 0, tile = 0;
  double share = 1.0;    // the view's rectangle over the G-buffer's area
  int cascades = 0;      // water cascades the lookups read
  int slots = 1;         // cascade lookups compiled in (waterCascadeSlots)
  bool war = false;      // the frame's model is WavefrontAreaRatio (its window is read)
  int localFetches = 0;  // lookup_work.h's localWaterFetches with Feature::LocalWater, else 0
  // The G-buffer's depth (and with `gbuffer` its normal and albedo) within the view, the water,
  // the shadow map and the fields the lookups read.
  TrafficList traffic(bool gbuffer) const;
};

class CausticsPass {
 public:
  // Builds the programs for the context's features and the GL objects (DSA: binds nothing).
  Result init(const CreateDesc& desc, std::string& error);

  // Attaches the host target (and the view's raw output, resized to it when needed), sizes the
  // view's reduced lookups when used, uploads the block; `view` is drawn with until the next
  // prepare. GL_ERROR with a message when the framebuffer is incomplete.
  Result prepare(const FrameDesc& frame, const ValidatedTextures& textures,
                 const shared::CausticsBlock& block, CausticsViewTextures& view,
                 std::string& error);
  // The variant of the caustics program that reads the tile irradiance: `groups` RGBA fetches
  // per cascade (1 or 2) for the cascades in `cascadeMask` (bit c: cascade c); `physical`: the
  // WavefrontAreaRatio window, continued beyond its edge by the tile irradiance (looked up per
  // pixel), else the TileIrradiance model alone, its lookups at every pixel or at half
  // resolution (`reduced`: then a lookup program and an upsampling caustics program). Built the
  // first time a frame needs it: a context that never uses the field never compiles it.
  // Returns the variant's index for drawCaustics (>= 1).
  Result ensureTileProgram(int groups, int cascadeMask, bool reduced, bool physical, int& variant,
                           std::string& error);
  // Sets the pipeline state both passes use; call under a GlStateGuard. irradiance: the
  // WavefrontAreaRatio model's texture, tile: the tile irradiance (0 when not in use).
  void bindState(const FrameDesc& frame, const ValidatedTextures& textures, GLuint irradiance,
                 GLuint tile = 0);
  void drawFloor();
  const SeabedInputs& inputs() const { return bound_; }
  // tileVariant: 0 for the RayDeviation program (and WavefrontAreaRatio without a tile field),
  // else the variant ensureTileProgram returned (a reduced one draws its lookups first, then
  // blends them in: both inside the caustics pass's timing).
  void drawCaustics(int tileVariant = 0);
  // Lets go of the host's texture (our framebuffer must not keep it alive) and unbinds.
  void finish();
  // The pass was skipped in `view`: its raw output (if any) must read 0, resized to the target.
  void clearRaw(const ValidatedTextures& textures, CausticsViewTextures& view);

 private:
  Step causticsStep(int tileVariant) const;
  Step lookupsStep(int tileVariant) const;

  void ensureRaw(const ValidatedTextures& textures, CausticsViewTextures& view);
  void ensureReduced(int width, int height, CausticsViewTextures& view);
  void drawReducedLookups(const glkit::Program& program, int tileVariant);

  CreateDesc desc_{};
  glkit::Program caustics_, floor_;
  // Tile-irradiance variants: [physical, reduced][groups - 1][cascade mask], index
  // 1 + 32 * reduced + 64 * physical + 16 * (groups - 1) + mask (a physical one is never
  // reduced); the reduced ones' lookups in tileLookups_.
  static constexpr int kTileMasks = 1 << kMaxCascades;
  static constexpr int kTileVariants = 2 * kTileMasks;
  glkit::Program tileCaustics_[3 * kTileVariants];
  glkit::Program tileLookups_[kTileVariants];
  // The floor draws through its own framebuffer with the same attachments: the switch makes a
  // software rasterizer start a new scene, so its timer queries separate the two passes.
  glkit::Framebuffer framebuffer_, floorFramebuffer_;
  glkit::VertexArray vertexArray_;
  glkit::Buffer uniformBuffer_;
  glkit::Sampler pointSampler_, waterMipSampler_, waterLinearSampler_;
  glkit::Sampler shadowForwardSampler_, shadowReverseSampler_, irradianceSampler_;
  glkit::Sampler tileSampler_;
  SeabedInputs bound_;
  CausticsViewTextures* view_ = nullptr;  // the view prepare() set up
  ValidatedTextures viewport_;            // its rectangle in the target
};

}  // namespace postfx::detail
