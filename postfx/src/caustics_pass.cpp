#include "caustics_pass.h"

#include <postfx/testing.h>

#include "host_target.h"

#include <string>

#include <glkit/texture.h>

#include "shader_library.h"

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
  d += std::string("#define POSTFX_PHYSICAL ") + flag(Feature::PhysicalCaustics) + "\n";
  d += std::string("#define POSTFX_TRIPLANAR_WALLS ") + flag(Feature::TriplanarWalls) + "\n";
  d += std::string("#define POSTFX_WATER_SINGLE_2D ") +
       (desc.waterTexture == WaterTextureType::Single2D ? "1" : "0") + "\n";
  d += "#define POSTFX_CASCADE_SLOTS " + std::to_string(waterCascadeSlots(desc)) + "\n";
  return d;
}

namespace {

GLuint makeShadowSampler(GLenum compare, const char* name) {
  GLuint sampler = glkit::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, name);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glSamplerParameteri(sampler, GL_TEXTURE_COMPARE_FUNC, static_cast<GLint>(compare));
  return sampler;
}

void deleteSampler(GLuint& sampler) {
  if (sampler != 0) glDeleteSamplers(1, &sampler);
  sampler = 0;
}

}  // namespace

CausticsPass::~CausticsPass() {
  release();
}

Result CausticsPass::init(const CreateDesc& desc, std::string& error) {
  release();
  desc_ = desc;
  const std::string defines = shaderDefines(desc);
  GLuint program = 0;
  if (!glkit::buildProgram(shaderLibrary(),
                           {{GL_VERTEX_SHADER, "postfx/fullscreen.vert"},
                            {GL_FRAGMENT_SHADER, "postfx/caustics.frag"}},
                           defines, "postfx.caustics", program, error))
    return Result::ShaderCompileFailed;
  caustics_ = glkit::Program(program);
  if (hasFeature(desc.features, testing::BenchmarkFloor)) {
    if (!glkit::buildProgram(shaderLibrary(),
                             {{GL_VERTEX_SHADER, "postfx/fullscreen.vert"},
                              {GL_FRAGMENT_SHADER, "postfx/floor.frag"}},
                             defines, "postfx.floor", program, error)) {
      release();
      return Result::ShaderCompileFailed;
    }
    floor_ = glkit::Program(program);
  }

  const bool raw = hasFeature(desc.features, testing::RawCausticOutput);
  const GLenum drawBuffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
  glCreateFramebuffers(1, &framebuffer_);
  glkit::label(GL_FRAMEBUFFER, framebuffer_, "postfx.caustics.framebuffer");
  glNamedFramebufferDrawBuffers(framebuffer_, raw ? 2 : 1, drawBuffers);
  if (floor_.id() != 0) {
    glCreateFramebuffers(1, &floorFramebuffer_);
    glkit::label(GL_FRAMEBUFFER, floorFramebuffer_, "postfx.floor.framebuffer");
    glNamedFramebufferDrawBuffers(floorFramebuffer_, raw ? 2 : 1, drawBuffers);
  }
  glCreateVertexArrays(1, &vertexArray_);
  glkit::label(GL_VERTEX_ARRAY, vertexArray_, "postfx.fullscreen.vao");
  glCreateBuffers(1, &uniformBuffer_);
  glNamedBufferStorage(uniformBuffer_, sizeof(shared::CausticsBlock), nullptr,
                       GL_DYNAMIC_STORAGE_BIT);
  glkit::label(GL_BUFFER, uniformBuffer_, "postfx.caustics.block");

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
  if (hasFeature(desc.features, Feature::PhysicalCaustics))
    irradianceSampler_ =
        glkit::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "postfx.sampler.irradiance");
  return Result::Ok;
}

void CausticsPass::release() {
  caustics_ = glkit::Program();
  floor_ = glkit::Program();
  for (glkit::Program& p : tileCaustics_) p = glkit::Program();
  if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
  if (floorFramebuffer_ != 0) glDeleteFramebuffers(1, &floorFramebuffer_);
  if (vertexArray_ != 0) glDeleteVertexArrays(1, &vertexArray_);
  if (uniformBuffer_ != 0) glDeleteBuffers(1, &uniformBuffer_);
  if (rawTexture_ != 0) glDeleteTextures(1, &rawTexture_);
  framebuffer_ = floorFramebuffer_ = vertexArray_ = uniformBuffer_ = rawTexture_ = 0;
  rawWidth_ = rawHeight_ = 0;
  deleteSampler(pointSampler_);
  deleteSampler(waterMipSampler_);
  deleteSampler(waterLinearSampler_);
  deleteSampler(shadowForwardSampler_);
  deleteSampler(shadowReverseSampler_);
  deleteSampler(irradianceSampler_);
  deleteSampler(tileSampler_);
}

Result CausticsPass::ensureTileProgram(int groups, int cascadeMask, int& variant,
                                       std::string& error) {
  const int g = groups > 1 ? 2 : 1;
  const int mask = cascadeMask & (kTileMasks - 1);
  const int index = kTileMasks * (g - 1) + mask;
  variant = 1 + index;
  glkit::Program& program = tileCaustics_[index];
  if (program.id() != 0) return Result::Ok;
  // The window model's lookup is compiled out: the two models never run together.
  std::string defines = shaderDefines(desc_);
  defines += "#undef POSTFX_PHYSICAL\n#define POSTFX_PHYSICAL 0\n";
  defines += "#define POSTFX_TILE_IRRADIANCE 1\n";
  defines += "#define POSTFX_TILE_GROUPS " + std::to_string(g) + "\n";
  defines += "#define POSTFX_TILE_CASCADES " + std::to_string(mask) + "\n";
  GLuint id = 0;
  if (!glkit::buildProgram(shaderLibrary(),
                           {{GL_VERTEX_SHADER, "postfx/fullscreen.vert"},
                            {GL_FRAGMENT_SHADER, "postfx/caustics.frag"}},
                           defines, "postfx.caustics_tile", id, error))
    return Result::ShaderCompileFailed;
  program = glkit::Program(id);
  return Result::Ok;
}

void CausticsPass::ensureRaw(int width, int height) {
  if (!hasFeature(desc_.features, testing::RawCausticOutput)) return;
  if (rawTexture_ != 0 && rawWidth_ == width && rawHeight_ == height) return;
  if (rawTexture_ != 0) glDeleteTextures(1, &rawTexture_);
  glCreateTextures(GL_TEXTURE_2D, 1, &rawTexture_);
  glTextureStorage2D(rawTexture_, 1, GL_R16F, width, height);
  glTextureParameteri(rawTexture_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(rawTexture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glkit::label(GL_TEXTURE, rawTexture_, "postfx.caustics.raw");
  rawWidth_ = width;
  rawHeight_ = height;
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT1, rawTexture_, 0);
  if (floorFramebuffer_ != 0)
    glNamedFramebufferTexture(floorFramebuffer_, GL_COLOR_ATTACHMENT1, rawTexture_, 0);
}

void CausticsPass::clearRaw(int width, int height) {
  if (!hasFeature(desc_.features, testing::RawCausticOutput)) return;
  ensureRaw(width, height);
  // A texture operation: no framebuffer, scissor or mask state involved.
  glClearTexImage(rawTexture_, 0, GL_RED, GL_FLOAT, nullptr);
}

Result CausticsPass::prepare(const FrameDesc& frame, const ValidatedTextures& textures,
                             const shared::CausticsBlock& block, std::string& error) {
  ensureRaw(textures.width, textures.height);
  if (floorFramebuffer_ != 0)
    glNamedFramebufferTexture(floorFramebuffer_, GL_COLOR_ATTACHMENT0, frame.target.texture, 0);
  if (!attachHostTarget(framebuffer_, frame.target.texture, "caustics", error)) {
    finish();
    return Result::GlError;
  }
  glNamedBufferSubData(uniformBuffer_, 0, sizeof(block), &block);
  return Result::Ok;
}

void CausticsPass::bindState(const FrameDesc& frame, const ValidatedTextures& textures,
                             GLuint irradiance, GLuint tile) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(textures.width),
                     static_cast<float>(textures.height));
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
  glBindVertexArray(vertexArray_);
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_CAUSTICS_BLOCK_BINDING, uniformBuffer_);

  glBindTextureUnit(kDepthUnit, frame.depth.texture);
  glBindTextureUnit(kNormalUnit, frame.normal.texture);
  glBindTextureUnit(kAlbedoUnit, frame.albedo.texture);
  const GLuint pointSamplers[] = {pointSampler_, pointSampler_, pointSampler_};
  glBindSamplers(kDepthUnit, 3, pointSamplers);
  // Without water (object caustics only) nothing samples the unit; binding 0 there would unbind
  // every target of the unit, which the state guard does not restore.
  if (frame.water.texture.texture != 0) {
    glBindTextureUnit(kWaterUnit, frame.water.texture.texture);
    glBindSampler(kWaterUnit, textures.waterMipmapped ? waterMipSampler_ : waterLinearSampler_);
  }
  if (hasFeature(desc_.features, Feature::ShadowMask)) {
    glBindTextureUnit(kShadowUnit, frame.shadow.depth.texture);
    glBindSampler(kShadowUnit, frame.shadow.depthConvention == DepthConvention::ReverseZ
                                   ? shadowReverseSampler_
                                   : shadowForwardSampler_);
  }
  if (irradiance != 0) {
    glBindTextureUnit(kIrradianceUnit, irradiance);
    glBindSampler(kIrradianceUnit, irradianceSampler_);
  }
  if (tile != 0) {  // the same unit: the two models never run together
    glBindTextureUnit(kIrradianceUnit, tile);
    glBindSampler(kIrradianceUnit, tileSampler_);
  }
}

void CausticsPass::drawFloor() {
  if (floor_.id() == 0) return;
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, floorFramebuffer_);
  glUseProgram(floor_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void CausticsPass::drawCaustics(int tileVariant) {
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_);
  glUseProgram(tileVariant > 0 ? tileCaustics_[tileVariant - 1].id() : caustics_.id());
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void CausticsPass::finish() {
  glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
  if (floorFramebuffer_ != 0)
    glNamedFramebufferTexture(floorFramebuffer_, GL_COLOR_ATTACHMENT0, 0, 0);
}

}  // namespace postfx::detail
