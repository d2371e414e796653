#include "god_rays/godrays_pass.h"

#include <glkit/texture.h>

#include "core/host_target.h"
#include "god_rays/godrays_constants.h"
#include "seabed_caustics/tile_irradiance_pass.h"

#include "core/shader_library.h"

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
  reducedFramebuffer_ = glkit::createFramebuffer("postfx.god_rays.reduced_framebuffer");
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

void GodRaysPass::ensureReduced(int w, int h) {
  if (reducedTexture_ && reducedWidth_ == w && reducedHeight_ == h) return;
  reducedTexture_.reset();  // the old size goes first: never two of them allocated at once
  reducedTexture_ = glkit::createTexture(GL_TEXTURE_2D, "postfx.god_rays.reduced");
  // Light and distance as four halves (godrays.frag's outReduced): 8 bytes a texel, as RGBA16F,
  // but the upsample gathers a pixel's four texels with two fetches instead of four.
  glTextureStorage2D(reducedTexture_.id(), 1, GL_RG32UI, w, h);
  glNamedFramebufferTexture(reducedFramebuffer_.id(), GL_COLOR_ATTACHMENT0, reducedTexture_.id(),
                            0);
  reducedWidth_ = w;
  reducedHeight_ = h;
}

Result GodRaysPass::prepare(const FrameDesc& frame, int width, int height,
                            const shared::GodRaysBlock& block, std::string& error) {
  const GodRayResolution resolution = frame.godRays.resolution;
  if (resolution != GodRayResolution::Full) {
    ensureReduced(godRayReducedSize(width, resolution), godRayReducedSize(height, resolution));
    // An allocation the driver refused leaves the march framebuffer incomplete: found here,
    // before anything is drawn.
    if (glCheckNamedFramebufferStatus(reducedFramebuffer_.id(), GL_DRAW_FRAMEBUFFER) !=
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

void GodRaysPass::draw(const FrameDesc& frame, int width, int height, int tileVariant) {
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_GODRAYS_BLOCK_BINDING, uniformBuffer_.id());
  const GLuint full = tileVariant > 0 ? tileFull_[tileVariant - 1].id() : full_.id();
  const GLuint reduced = tileVariant > 0 ? tileReduced_[tileVariant - 1].id() : reduced_.id();
  if (frame.godRays.resolution == GodRayResolution::Full) {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
    glUseProgram(full);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    return;
  }
  // March at reduced size, unblended: every texel is written (light and distance).
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, reducedFramebuffer_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(reducedWidth_),
                     static_cast<float>(reducedHeight_));
  glDisablei(GL_BLEND, 0);
  glUseProgram(reduced);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  // Upsample, added into the target.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(width), static_cast<float>(height));
  glEnablei(GL_BLEND, 0);
  glBindTextureUnit(POSTFX_UNIT_GODRAYS_REDUCED, reducedTexture_.id());
  glBindSampler(POSTFX_UNIT_GODRAYS_REDUCED, reducedSampler_.id());
  glUseProgram(upsample_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void GodRaysPass::finish() {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace postfx::detail
