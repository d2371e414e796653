#include "seabed_caustics/caustics_pass.h"

#include <postfx/testing.h>

#include "core/host_target.h"

#include <algorithm>
#include <string>

#include <glkit/texture.h>

#include "core/shader_library.h"
#include "core/work_instrumentation.h"
#include "seabed_caustics/lookup_work.h"
#include "seabed_caustics/tile_irradiance_pass.h"

// bindState binds the G-buffer's three samplers in one call.
static_assert(POSTFX_UNIT_NORMAL == POSTFX_UNIT_DEPTH + 1 &&
                  POSTFX_UNIT_ALBEDO == POSTFX_UNIT_DEPTH + 2,
              "the G-buffer units are consecutive");

namespace postfx::detail {

std::string shaderDefines(const CreateDesc& desc) {
  auto flag = [&desc](Feature f) { return hasFeature(desc.features, f) ? "1" : "0"; };
  std::string d;
  d += "#define POSTFX_DEPTH_CONVENTION " + std::to_string(static_cast<int>(desc.depthConvention)) +
       "\n";
  d += "#define POSTFX_NORMAL_ENCODING " + std::to_string(static_cast<int>(desc.normalEncoding)) +
       "\n";
  d += std::string("#define POSTFX_DISPERSION ") + flag(Feature::Dispersion) + "\n";
  d += std::string("#define POSTFX_SHADOW_MASK ") + flag(Feature::ShadowMask) + "\n";
  d += std::string("#define POSTFX_RAW_OUTPUT ") + flag(testing::RawCausticOutput) + "\n";
  d += std::string("#define POSTFX_WAVEFRONT_AREA_RATIO ") + flag(Feature::WavefrontAreaRatio) +
       "\n";
  d += std::string("#define POSTFX_TRIPLANAR_WALLS ") + flag(Feature::TriplanarWalls) + "\n";
  d += std::string("#define POSTFX_LOCAL_WATER ") + flag(Feature::LocalWater) + "\n";
  d += std::string("#define POSTFX_VOLUME_CAUSTICS ") + flag(Feature::VolumeCaustics) + "\n";
  d += std::string("#define POSTFX_WATER_SINGLE_2D ") +
       (desc.waterTexture == WaterTextureType::Single2D ? "1" : "0") + "\n";
  d += "#define POSTFX_CASCADE_SLOTS " + std::to_string(waterCascadeSlots(desc)) + "\n";
  if (hasFeature(desc.features, testing::CountShaderWork)) d += kCountWorkDefine;
  return d;
}

namespace {

glkit::Sampler makeShadowSampler(GLenum compare, const char* name) {
  glkit::Sampler sampler = glkit::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, name);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(sampler.id(), GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(compare));
  return sampler;
}

glkit::Framebuffer makeFramebuffer(int drawBuffers, const char* name) {
  const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glkit::Framebuffer framebuffer = glkit::createFramebuffer(name);
  glNamedFramebufferDrawBuffers(framebuffer.id(), drawBuffers, buffers);
  return framebuffer;
}

}  // namespace

Result CausticsPass::init(const CreateDesc& desc, std::string& error) {
  desc_ = desc;
  const std::string defines = shaderDefines(desc);
  Result r = buildPrograms(
      defines,
      {{caustics_,
        "postfx.caustics",
        {kFullScreenVertex, {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/caustics.frag"}}}},
      error);
  const bool floor = hasFeature(desc.features, testing::BenchmarkFloor);
  if (r == Result::Ok && floor)
    r = buildPrograms(
        defines,
        {{floor_,
          "postfx.floor",
          {kFullScreenVertex, {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/floor.frag"}}}},
        error);
  if (r != Result::Ok) return r;

  const int drawBuffers = hasFeature(desc.features, testing::RawCausticOutput) ? 2 : 1;
  framebuffer_ = makeFramebuffer(drawBuffers, "postfx.caustics.framebuffer");
  if (floor) floorFramebuffer_ = makeFramebuffer(drawBuffers, "postfx.floor.framebuffer");
  vertexArray_ = glkit::createVertexArray("postfx.fullscreen.vao");
  uniformBuffer_ = glkit::createBuffer(sizeof(shared::CausticsBlock), nullptr,
                                       GL_DYNAMIC_STORAGE_BIT, "postfx.caustics.block");

  pointSampler_ =
      glkit::createSampler(GL_NEAREST, GL_NEAREST, GL_CLAMP_TO_EDGE, "postfx.sampler.point");
  waterMipSampler_ = glkit::createSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_REPEAT,
                                          "postfx.sampler.water_mip");
  waterLinearSampler_ =
      glkit::createSampler(GL_LINEAR, GL_LINEAR, GL_REPEAT, "postfx.sampler.water");
  if (hasFeature(desc.features, Feature::ShadowMask)) {
    shadowForwardSampler_ = makeShadowSampler(GL_LEQUAL, "postfx.sampler.shadow_forward");
    shadowReverseSampler_ = makeShadowSampler(GL_GEQUAL, "postfx.sampler.shadow_reverse_z");
  }
  // The tile repeats: filtering wraps across its edge.
  tileSampler_ = glkit::createSampler(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, GL_REPEAT,
                                      "postfx.sampler.tile_irradiance");
  if (hasFeature(desc.features, Feature::WavefrontAreaRatio))
    irradianceSampler_ = glkit::createSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
                                              "postfx.sampler.irradiance");
  return Result::Ok;
}

Result CausticsPass::ensureTileProgram(int groups, int cascadeMask, bool reduced, bool physical,
                                       int& variant, std::string& error) {
  reduced = reduced && !physical;
  const int g = groups > 1 ? 2 : 1;
  const int mask = cascadeMask & (kTileMasks - 1);
  const int index = kTileMasks * (g - 1) + mask;
  variant = 1 + (physical ? 2 * kTileVariants : reduced ? kTileVariants : 0) + index;
  glkit::Program& program = tileCaustics_[variant - 1];
  if (program.id() != 0) return Result::Ok;
  std::string tileDefines = tileVariantDefines(g, mask, physical);
  tileDefines += reduced ? "#define POSTFX_TILE_REDUCED 1\n" : "#define POSTFX_TILE_REDUCED 0\n";
  const std::string defines = shaderDefines(desc_);
  if (!reduced)
    return buildPrograms(
        defines,
        {{program,
          physical ? "postfx.caustics_wavefront_area_ratio" : "postfx.caustics_tile",
          {kFullScreenVertex, {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/caustics.frag"}},
          tileDefines}},
        error);
  return buildPrograms(
      defines,
      {{program,
        "postfx.caustics_tile_upsampled",
        {kFullScreenVertex, {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/caustics.frag"}},
        tileDefines},
       {tileLookups_[index],
        "postfx.caustics_tile_lookups",
        {kFullScreenVertex,
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/tile_irradiance_reduced.frag"}},
        tileDefines}},
      error);
}

std::uint64_t CausticsViewTextures::allocatedBytes() const {
  return std::uint64_t(rawWidth) * std::uint64_t(rawHeight) * 2 +         // R16F
         std::uint64_t(reducedWidth) * std::uint64_t(reducedHeight) * 4;  // R32UI
}

void CausticsPass::ensureReduced(int width, int height, CausticsViewTextures& view) {
  const int w = (width + 1) / 2, h = (height + 1) / 2;  // texel i: pixel 2i
  if (view.reduced && view.reducedWidth == w && view.reducedHeight == h) return;
  view.reduced.reset();  // the old size goes first: never two of them allocated at once
  view.reduced = glkit::createTexture(GL_TEXTURE_2D, "postfx.caustics.tile_lookups");
  glTextureStorage2D(view.reduced.id(), 1, GL_R32UI, w, h);  // two halves
  view.reducedWidth = w;
  view.reducedHeight = h;
  if (!view.reducedFramebuffer)
    view.reducedFramebuffer = makeFramebuffer(1, "postfx.caustics.tile_lookups");
  glNamedFramebufferTexture(view.reducedFramebuffer.id(), GL_COLOR_ATTACHMENT0, view.reduced.id(),
                            0);
}

void CausticsPass::drawReducedLookups(const glkit::Program& program, int tileVariant) {
  // Under bindState's state, with the tile irradiance on its unit: its own target, unblended.
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, view_->reducedFramebuffer.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(view_->reducedWidth),
                     static_cast<float>(view_->reducedHeight));
  glDisablei(GL_BLEND, 0);
  glUseProgram(program.id());
  work::drawArrays(lookupsStep(tileVariant), GL_TRIANGLES, 0, 3);
  // Back to bindState's: the upsample reads the lookups on the irradiance unit, texel by texel.
  glViewportIndexedf(0, static_cast<float>(viewport_.x), static_cast<float>(viewport_.y),
                     static_cast<float>(viewport_.width), static_cast<float>(viewport_.height));
  glEnablei(GL_BLEND, 0);
  glBindTextureUnit(POSTFX_UNIT_TILE_REDUCED, view_->reduced.id());
  glBindSampler(POSTFX_UNIT_TILE_REDUCED, pointSampler_.id());
}

void CausticsPass::ensureRaw(const ValidatedTextures& textures, CausticsViewTextures& view) {
  if (!hasFeature(desc_.features, testing::RawCausticOutput)) return;
  const int width = textures.targetWidth, height = textures.targetHeight;
  if (!(view.raw && view.rawWidth == width && view.rawHeight == height)) {
    view.raw.reset();  // the old size goes first: never two of them allocated at once
    view.raw = glkit::createTexture(GL_TEXTURE_2D, "postfx.caustics.raw");
    const GLuint raw = view.raw.id();
    glTextureStorage2D(raw, 1, GL_R16F, width, height);
    glTextureParameteri(raw, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(raw, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    // Outside its viewport a view's raw output reads 0, as a skipped pass's does.
    glClearTexImage(raw, 0, GL_RED, GL_FLOAT, nullptr);
    view.rawWidth = width;
    view.rawHeight = height;
  }
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT1, view.raw.id(), 0);
  if (floorFramebuffer_)
    glNamedFramebufferTexture(floorFramebuffer_.id(), GL_COLOR_ATTACHMENT1, view.raw.id(), 0);
}

void CausticsPass::clearRaw(const ValidatedTextures& textures, CausticsViewTextures& view) {
  if (!hasFeature(desc_.features, testing::RawCausticOutput)) return;
  ensureRaw(textures, view);
  // A texture operation: no framebuffer, scissor or mask state involved.
  glClearTexSubImage(view.raw.id(), 0, textures.x, textures.y, 0, textures.width, textures.height,
                     1, GL_RED, GL_FLOAT, nullptr);
}

Result CausticsPass::prepare(const FrameDesc& frame, const ValidatedTextures& textures,
                             const shared::CausticsBlock& block, CausticsViewTextures& view,
                             std::string& error) {
  view_ = &view;
  viewport_ = textures;
  ensureRaw(textures, view);
  if (frame.caustics.enabled && frame.caustics.model == CausticsModel::TileIrradiance &&
      frame.caustics.tileLookupResolution == CausticsLookupResolution::Half)
    ensureReduced(textures.width, textures.height, view);
  if (floorFramebuffer_)
    glNamedFramebufferTexture(floorFramebuffer_.id(), GL_COLOR_ATTACHMENT0, frame.target.texture,
                              0);
  if (!attachHostTarget(framebuffer_.id(), frame.target.texture, "caustics", error)) {
    finish();
    return Result::GlError;
  }
  glNamedBufferSubData(uniformBuffer_.id(), 0, sizeof(block), &block);
  return Result::Ok;
}

void CausticsPass::bindState(const FrameDesc& frame, const ValidatedTextures& textures,
                             GLuint irradiance, GLuint tile) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, static_cast<float>(textures.x), static_cast<float>(textures.y),
                     static_cast<float>(textures.width), static_cast<float>(textures.height));
  glDisablei(GL_SCISSOR_TEST, 0);
  glEnablei(GL_BLEND, 0);
  glBlendFuncSeparatei(0, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  glBlendEquationSeparatei(0, GL_FUNC_ADD, GL_FUNC_ADD);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisablei(GL_BLEND, 1);
  glColorMaski(1, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_CULL_FACE);
  glDisable(GL_RASTERIZER_DISCARD);
  glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  // The vertex shader writes no gl_ClipDistance: an enabled one would clip undefinedly.
  GLint maxClip = 0;
  glGetIntegerv(GL_MAX_CLIP_DISTANCES, &maxClip);
  for (GLint i = 0; i < maxClip && i < 8; ++i)
    glDisable(static_cast<GLenum>(GL_CLIP_DISTANCE0 + i));
  glBindVertexArray(vertexArray_.id());
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_CAUSTICS_BLOCK_BINDING, uniformBuffer_.id());

  bound_ = {frame.depth.texture,
            frame.normal.texture,
            frame.albedo.texture,
            frame.water.texture.texture,
            hasFeature(desc_.features, Feature::ShadowMask) ? frame.shadow.depth.texture : 0u,
            irradiance,
            tile,
            double(textures.width) * textures.height /
                std::max(1.0, double(textures.targetWidth) * textures.targetHeight),
            frame.water.texture.texture != 0
                ? std::min(frame.water.cascadeCount, waterCascadeSlots(desc_))
                : 0,
            waterCascadeSlots(desc_),
            frame.caustics.model == CausticsModel::WavefrontAreaRatio,
            hasFeature(desc_.features, Feature::LocalWater) ? localWaterFetches(frame) : 0};
  glBindTextureUnit(POSTFX_UNIT_DEPTH, frame.depth.texture);
  glBindTextureUnit(POSTFX_UNIT_NORMAL, frame.normal.texture);
  glBindTextureUnit(POSTFX_UNIT_ALBEDO, frame.albedo.texture);
  const GLuint point = pointSampler_.id();
  const GLuint pointSamplers[] = {point, point, point};
  glBindSamplers(POSTFX_UNIT_DEPTH, 3, pointSamplers);
  // Without water (object caustics only) nothing samples the unit; binding 0 there would unbind
  // every target of the unit, which the state guard does not restore.
  if (frame.water.texture.texture != 0) {
    glBindTextureUnit(POSTFX_UNIT_WATER, frame.water.texture.texture);
    glBindSampler(POSTFX_UNIT_WATER,
                  textures.waterMipmapped ? waterMipSampler_.id() : waterLinearSampler_.id());
  }
  if (hasFeature(desc_.features, Feature::ShadowMask)) {
    glBindTextureUnit(POSTFX_UNIT_SHADOW, frame.shadow.depth.texture);
    glBindSampler(POSTFX_UNIT_SHADOW, frame.shadow.depthConvention == DepthConvention::ReverseZ
                                          ? shadowReverseSampler_.id()
                                          : shadowForwardSampler_.id());
  }
  if (irradiance != 0) {
    glBindTextureUnit(POSTFX_UNIT_IRRADIANCE, irradiance);
    glBindSampler(POSTFX_UNIT_IRRADIANCE, irradianceSampler_.id());
  }
  if (tile != 0) {
    glBindTextureUnit(POSTFX_UNIT_TILE_IRRADIANCE, tile);
    glBindSampler(POSTFX_UNIT_TILE_IRRADIANCE, tileSampler_.id());
  }
}

TrafficList SeabedInputs::traffic(bool gbuffer) const {
  TrafficList t;
  t.add(Traffic::readLevel0(depth, share));
  if (gbuffer) {
    t.add(Traffic::readLevel0(normal, share));
    t.add(Traffic::readLevel0(albedo, share));
  }
  t.add(Traffic::read(water));
  t.add(Traffic::read(shadow));
  t.add(Traffic::read(irradiance));
  t.add(Traffic::read(tile));
  return t;
}

// caustics.frag on its full path (an underwater pixel facing the light, lit): the G-buffer's
// three texels, the shadow map, then the model's lookups (lookup_work.h) and the local water's.
// A reduced TileIrradiance variant reads one gather of the lookups instead of its own.
Step CausticsPass::causticsStep(int tileVariant) const {
  const bool shadow = hasFeature(desc_.features, Feature::ShadowMask);
  int fetches = 3 + (shadow ? kShadowFetches : 0) + bound_.localFetches;
  const int slots = bound_.slots;
  if (tileVariant == 0) {
    const int projections = hasFeature(desc_.features, Feature::TriplanarWalls) ? 3 : 1;
    fetches += waterSlopeFetches(bound_.cascades, projections) + (bound_.war ? kWindowFetches : 0);
  } else {
    const int index = (tileVariant - 1) % kTileVariants;
    const bool reduced = tileVariant > kTileVariants && tileVariant <= 2 * kTileVariants;
    const bool physical = tileVariant > 2 * kTileVariants;
    if (reduced)
      fetches += 1;  // the gather of four lookups
    else
      fetches += tileIrradianceFetches(index % kTileMasks, index / kTileMasks + 1, bound_.cascades,
                                       slots) +
                 (physical ? kWindowFetches : 0);
  }
  return {"caustics.light", {}, {double(fetches), 0.0}, bound_.traffic(true)};
}

// tile_irradiance_reduced.frag per texel of half the view: depth, normal, the field's lookup.
Step CausticsPass::lookupsStep(int tileVariant) const {
  const int index = (tileVariant - 1) % kTileVariants;
  const int fetches = 2 + tileIrradianceFetches(index % kTileMasks, index / kTileMasks + 1,
                                                bound_.cascades, bound_.slots);
  TrafficList t;
  t.add(Traffic::readLevel0(bound_.depth, bound_.share));
  t.add(Traffic::readLevel0(bound_.normal, bound_.share));
  t.add(Traffic::read(bound_.water));
  t.add(Traffic::read(bound_.tile));
  return {"caustics.tile_lookups", {}, {double(fetches), 0.0}, t};
}

void CausticsPass::drawFloor() {
  if (floor_.id() == 0) return;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, floorFramebuffer_.id());
  glUseProgram(floor_.id());
  // floor.frag: the G-buffer's three texels, each cascade once, the shadow map.
  const bool shadow = hasFeature(desc_.features, Feature::ShadowMask);
  const StageWork floor{double(3 + bound_.cascades + (shadow ? kShadowFetches : 0)), 0.0};
  work::drawArrays({"floor.inputs", {}, floor, bound_.traffic(true)}, GL_TRIANGLES, 0, 3);
}

void CausticsPass::drawCaustics(int tileVariant) {
  if (tileVariant > kTileVariants && tileVariant <= 2 * kTileVariants)
    drawReducedLookups(tileLookups_[tileVariant - 1 - kTileVariants], tileVariant);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glUseProgram(tileVariant > 0 ? tileCaustics_[tileVariant - 1].id() : caustics_.id());
  work::drawArrays(causticsStep(tileVariant), GL_TRIANGLES, 0, 3);
}

void CausticsPass::finish() {
  glNamedFramebufferTexture(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
  if (floorFramebuffer_)
    glNamedFramebufferTexture(floorFramebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace postfx::detail
