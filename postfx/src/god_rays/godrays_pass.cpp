#include "god_rays/godrays_pass.h"

#include <glkit/texture.h>

#include "core/host_target.h"
#include "core/validation.h"
#include "god_rays/godrays_constants.h"
#include "seabed_caustics/tile_irradiance_pass.h"

#include "core/shader_library.h"
#include "seabed_caustics/caustics_pass.h"
#include "seabed_caustics/lookup_work.h"

namespace postfx::detail {
Result GodRaysPass::init(const std::string& defines, std::string& error) {
  defines_ = defines;
  const glkit::ShaderStage march{GL_FRAGMENT_SHADER, "postfx/god_rays/godrays.frag"};
  const Result r = buildPrograms(
      defines,
      {{full_, "postfx.god_rays", {kFullScreenVertex, march}, "#define POSTFX_GODRAYS_REDUCED 0\n"},
       {reduced_,
        "postfx.god_rays.reduced",
        {kFullScreenVertex, march},
        "#define POSTFX_GODRAYS_REDUCED 1\n"},
       {upsample_,
        "postfx.god_rays.upsample",
        {kFullScreenVertex, {GL_FRAGMENT_SHADER, "postfx/god_rays/godrays_upsample.frag"}}}},
      error);
  if (r != Result::Ok) return r;
  framebuffer_ = glkit::createFramebuffer("postfx.god_rays.framebuffer");
  uniformBuffer_ = glkit::createBuffer(sizeof(shared::GodRaysBlock), nullptr,
                                       GL_DYNAMIC_STORAGE_BIT, "postfx.god_rays.block");
  reducedSampler_ = glkit::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE,
                                         "postfx.sampler.god_rays_reduced");
  return Result::Ok;
}

Result GodRaysPass::ensureTileProgram(int groups, int cascadeMask, bool physical, int& variant,
                                      std::string& error) {
  const int g = groups > 1 ? 2 : 1;
  const int index =
      (physical ? kTileVariants : 0) + kTileMasks * (g - 1) + (cascadeMask & (kTileMasks - 1));
  variant = 1 + index;
  if (tileFull_[index].id() != 0 && tileReduced_[index].id() != 0) return Result::Ok;
  const std::string tile = tileVariantDefines(g, cascadeMask & (kTileMasks - 1), physical);
  const glkit::ShaderStage march{GL_FRAGMENT_SHADER, "postfx/god_rays/godrays.frag"};
  return buildPrograms(defines_,
                       {{tileFull_[index],
                         "postfx.god_rays_tile",
                         {kFullScreenVertex, march},
                         tile + "#define POSTFX_GODRAYS_REDUCED 0\n"},
                        {tileReduced_[index],
                         "postfx.god_rays_tile.reduced",
                         {kFullScreenVertex, march},
                         tile + "#define POSTFX_GODRAYS_REDUCED 1\n"}},
                       error);
}

void GodRaysPass::ensureReduced(int w, int h, GodRaysViewTextures& view) {
  if (view.reduced && view.reducedWidth == w && view.reducedHeight == h) return;
  view.reduced.reset();  // the old size goes first: never two of them allocated at once
  view.reduced = glkit::createTexture(GL_TEXTURE_2D, "postfx.god_rays.reduced");
  // Light and distance as four halves (godrays.frag's outReduced): 8 bytes a texel, as RGBA16F,
  // but the upsample gathers a pixel's four texels with two fetches instead of four.
  glTextureStorage2D(view.reduced.id(), 1, GL_RG32UI, w, h);
  if (!view.reducedFramebuffer)
    view.reducedFramebuffer = glkit::createFramebuffer("postfx.god_rays.reduced_framebuffer");
  glNamedFramebufferTexture(view.reducedFramebuffer.id(), GL_COLOR_ATTACHMENT0, view.reduced.id(),
                            0);
  view.reducedWidth = w;
  view.reducedHeight = h;
}

Result GodRaysPass::prepare(const FrameDesc& frame, const ValidatedTextures& textures,
                            const shared::GodRaysBlock& block, GodRaysViewTextures& view,
                            std::string& error) {
  view_ = &view;
  viewport_[0] = textures.x;
  viewport_[1] = textures.y;
  viewport_[2] = textures.width;
  viewport_[3] = textures.height;
  const GodRayResolution resolution = frame.godRays.resolution;
  if (resolution != GodRayResolution::Full) {
    ensureReduced(godRayReducedSize(textures.width, resolution),
                  godRayReducedSize(textures.height, resolution), view);
    // An allocation the driver refused leaves the march framebuffer incomplete: found here,
    // before anything is drawn.
    if (glCheckNamedFramebufferStatus(view.reducedFramebuffer.id(), GL_DRAW_FRAMEBUFFER) !=
        GL_FRAMEBUFFER_COMPLETE) {
      error = "godRays: the reduced-resolution march texture could not be allocated";
      return Result::OutOfMemory;
    }
  }
  if (!attachHostTarget(framebuffer_.id(), frame.target.texture, "god-ray", error)) {
    finish();
    return Result::GlError;
  }
  glNamedBufferSubData(uniformBuffer_.id(), 0, sizeof(block), &block);
  return Result::Ok;
}

// godrays.frag on its full path (a ray that takes all sampleCount samples): the pixel's depth,
// then per sample the shadow map, the seabed model's lookups at one projection
// (lookup_work.h) and the local water's.
StageWork GodRaysPass::marchWork(const FrameDesc& frame, int tileVariant,
                                 const SeabedInputs& in) const {
  int perSample = (in.shadow != 0 ? kShadowFetches : 0) + in.localFetches;
  if (tileVariant == 0) {
    perSample += waterSlopeFetches(in.cascades, 1) + (in.war ? kWindowFetches : 0);
  } else {
    const int index = (tileVariant - 1) % kTileVariants;
    const bool physical = tileVariant - 1 >= kTileVariants;
    perSample +=
        tileIrradianceFetches(index % kTileMasks, index / kTileMasks + 1, in.cascades, in.slots) +
        (physical ? kWindowFetches : 0);
  }
  return {1.0 + double(frame.godRays.sampleCount) * perSample, 0.0};
}

void GodRaysPass::draw(const FrameDesc& frame, int tileVariant, const SeabedInputs& inputs) {
  const Step march{
      "god_rays.march", {}, marchWork(frame, tileVariant, inputs), inputs.traffic(false)};
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_GODRAYS_BLOCK_BINDING, uniformBuffer_.id());
  const GLuint full = tileVariant > 0 ? tileFull_[tileVariant - 1].id() : full_.id();
  const GLuint reduced = tileVariant > 0 ? tileReduced_[tileVariant - 1].id() : reduced_.id();
  if (frame.godRays.resolution == GodRayResolution::Full) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
    glUseProgram(full);
    work::drawArrays(march, GL_TRIANGLES, 0, 3);
    return;
  }
  // March at reduced size, unblended: every texel is written (light and distance).
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, view_->reducedFramebuffer.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(view_->reducedWidth),
                     static_cast<float>(view_->reducedHeight));
  glDisablei(GL_BLEND, 0);
  glUseProgram(reduced);
  work::drawArrays(march, GL_TRIANGLES, 0, 3);
  // Upsample, added into the view's rectangle of the target.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, static_cast<float>(viewport_[0]), static_cast<float>(viewport_[1]),
                     static_cast<float>(viewport_[2]), static_cast<float>(viewport_[3]));
  glEnablei(GL_BLEND, 0);
  glBindTextureUnit(POSTFX_UNIT_GODRAYS_REDUCED, view_->reduced.id());
  glBindSampler(POSTFX_UNIT_GODRAYS_REDUCED, reducedSampler_.id());
  glUseProgram(upsample_.id());
  // godrays_upsample.frag: the pixel's depth and two gathers of the reduced march.
  work::drawArrays(
      {"god_rays.upsample",
       {},
       {3.0, 0.0},
       {Traffic::readLevel0(inputs.depth, inputs.share), Traffic::read(view_->reduced.id())}},
      GL_TRIANGLES, 0, 3);
}

void GodRaysPass::finish() {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace postfx::detail
