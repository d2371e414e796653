#include "reflected_caustics/reflected_field_pass.h"

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

#include "core/block_check.h"
#include "core/frame_geometry.h"
#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/caustics_pass.h"
#include "seabed_caustics/grid_layer_draw.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {

Result ReflectedFieldPass::init(const std::string& defines, std::string& error) {
  // The triangle and point draws are the wavefront area ratio's own: they read grid points in
  // texels, whatever placed them; compiled to also write the light times its rays' drift.
  constexpr std::string_view drift = "#define POSTFX_GRID_DRIFT 1\n";
  Result r = buildPrograms(
      defines,
      {{vertices_,
        "postfx.reflected_caustics.grid",
        {{GL_COMPUTE_SHADER, "postfx/reflected_caustics/reflected_light_vertices.comp"}}},
       {triangles_,
        "postfx.reflected_caustics.triangles",
        {{GL_VERTEX_SHADER, "postfx/seabed_caustics/wavefront_area_ratio.vert"},
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/wavefront_area_ratio.frag"}},
        drift},
       {points_,
        "postfx.reflected_caustics.points",
        {{GL_VERTEX_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_points.vert"},
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_points.frag"}},
        drift}},
      error);
  if (r != Result::Ok) return r;
  r = spread_.init(defines, "postfx.reflected_caustics", error);
  if (r != Result::Ok) return r;
  framebuffer_ = glkit::createFramebuffer("postfx.reflected_caustics.framebuffer");
  const GLenum buffers[kReflectedChannels] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1,
                                              GL_COLOR_ATTACHMENT2};
  glNamedFramebufferDrawBuffers(framebuffer_.id(), kReflectedChannels, buffers);
  vertexArray_ = glkit::createVertexArray("postfx.reflected_caustics.vao");
  clampCount_ = glkit::createBuffer(2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT,
                                    "postfx.reflected_caustics.clamp_count");
  return Result::Ok;
}

Result ReflectedFieldPass::reserve(const FrameDesc& frame, std::string& error) {
  layout_ = reflectedLayout(frame);
  const int resolution = layout_.resolution, layers = layout_.layers;
  if (!(texture_ && textureResolution_ == resolution && textureLayers_ == layers)) {
    for (glkit::Texture& v : channelViews_) v.reset();
    texture_.reset();  // the old size goes first: never two allocated at once
    spread_.ensure(false, 0, 0);
    texture_ = glkit::createTexture(GL_TEXTURE_2D_ARRAY, "postfx.reflected_caustics.irradiance");
    // R32F with mips, as the refracted window's: exact additive sums, footprint-filtered lookups.
    // Three channels of `layers` layers each: the light, then its drift-weighted x and z sums.
    const int levels = wavefrontAreaRatioMipLevels(resolution);
    glTextureStorage3D(texture_.id(), levels, GL_R32F, resolution, resolution,
                       kReflectedChannels * layers);
    // One view per channel: the landing spread blurs `layers` layers of one texture.
    for (int c = 0; c < kReflectedChannels; ++c) {
      GLuint view = 0;
      glGenTextures(1, &view);
      glTextureView(view, GL_TEXTURE_2D_ARRAY, texture_.id(), GL_R32F, 0, GLuint(levels),
                    GLuint(c * layers), GLuint(layers));
      channelViews_[c] = glkit::Texture(view);
    }
    textureResolution_ = resolution;
    textureLayers_ = layers;
  }
  spread_.ensure(layout_.spread, resolution, layers);
  const std::uint64_t side = std::uint64_t(layout_.cells) + 1;
  const bool points = gridPoints_.ensure(side * side, "postfx.reflected_caustics.grid_points");
  if (glkit::storedWidth(texture_) != resolution || !points) {
    textureResolution_ = 0;
    error =
        "reflectedCaustics: the driver could not allocate the reflected light's layers "
        "(gridResolution " +
        std::to_string(resolution) + ")";
    return Result::OutOfMemory;
  }
  return Result::Ok;
}

void ReflectedFieldPass::draw(const FrameDesc& frame, const ValidatedTextures& textures,
                              const SeabedInputs& inputs) {
  layout_ = reflectedLayout(frame);
  const ReflectedLayout& l = layout_;
  const float zero = 0.0f;
  glClearTexImage(texture_.id(), 0, GL_RED, GL_FLOAT, &zero);  // every channel's layers
  const std::uint64_t levelBytes = textureBytes(texture_.id(), 4) * 3 / 4;  // R32F, level 0
  work::noteClear("reflected_caustics.clear", levelBytes);
  const GLuint zeros[2] = {0, 0};  // never read, kept from wrapping around
  glNamedBufferSubData(clampCount_.id(), 0, sizeof(zeros), zeros);

  const int pointsPerSide = l.cells + 1;
  const WaterSurface& water = frame.water;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const double flatR = shared::fresnelReflectance(static_cast<float>(sun.y), water.ior);
  const double texelsPerMetre = l.resolution / l.windowSize;
  // Triangles whose landing area is under half a texel go to the point draw, as the refracted
  // window's (WavefrontAreaRatioPass::draw says why half).
  const double cellTexels = l.cell * texelsPerMetre;
  const float pointRatio = static_cast<float>(0.5 * cellTexels * cellTexels / 0.5);
  const GLuint compute = vertices_.id();
  glProgramUniform1i(compute, 4, water.cascadeCount);
  glProgramUniform4f(compute, 6, static_cast<float>(sun.x), static_cast<float>(sun.y),
                     static_cast<float>(sun.z), water.ior);
  glProgramUniform4f(compute, 7, saturatedFloat(flatR > 0.0 ? 1.0 / flatR : 0.0),
                     static_cast<float>(texelsPerMetre), 0.0f, 0.0f);
  glProgramUniform1i(compute, 9, pointsPerSide);
  const glm::dvec2 corner =
      l.windowOrigin - glm::dvec2(frame.camera.position.x, frame.camera.position.z);
  glProgramUniform3f(compute, 10, static_cast<float>(corner.x),
                     static_cast<float>(water.level - frame.camera.position.y),
                     static_cast<float>(corner.y));
  setGridDrawUniforms(triangles_.id(), points_.id(), frame.reflectedCaustics.maxIrradiance,
                      pointsPerSide, l.resolution, pointRatio);

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(l.resolution),
                     static_cast<float>(l.resolution));
  glBindVertexArray(vertexArray_.id());
  glEnable(GL_PROGRAM_POINT_SIZE);
  // The drift channels add up as the light does (the caller set buffer 0's blend; the guard
  // restores every buffer's).
  for (GLuint b = 1; b < GLuint(kReflectedChannels); ++b) {
    glEnablei(GL_BLEND, b);
    glBlendFuncSeparatei(b, GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  }
  glBindTextureUnit(POSTFX_UNIT_GRID_POINTS, gridPoints_.view());
  glBindSampler(POSTFX_UNIT_GRID_POINTS, 0);
  const int texelsPerSide = std::max(textures.water.width, textures.water.height);
  const GLuint groups = static_cast<GLuint>((pointsPerSide + 15) / 16);
  for (int k = 0; k < l.layers; ++k) {
    glm::vec4 cascades[kMaxCascades];
    cascadeGridUniforms(water, l.gridOrigin[k], l.cell, texelsPerSide, cascades);
    glProgramUniform4fv(compute, 0, water.cascadeCount, &cascades[0].x);
    const glm::dvec2 gridLocal = l.gridOrigin[k] - l.windowOrigin;
    glProgramUniform4f(compute, 5, static_cast<float>(gridLocal.x), static_cast<float>(gridLocal.y),
                       static_cast<float>(l.cell), static_cast<float>(l.height[k]));
    glUseProgram(compute);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_GRID_POINTS, gridPoints_.buffer());
    // reflected_light_vertices.comp per grid point: each cascade's water, the shadow map.
    const double points = double(pointsPerSide) * pointsPerSide;
    work::dispatchCompute({"reflected_caustics.vertices",
                           {},
                           {perInvocation(water.cascadeCount + (inputs.shadow != 0 ? 1 : 0), points,
                                          groups * groups * 256.0)},
                           {Traffic::read(water.texture.texture), Traffic::read(inputs.shadow),
                            Traffic::writeBuffer(gridPoints_.buffer())}},
                          groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

    drawGridLayer({"reflected_caustics.triangles", "reflected_caustics.points"}, framebuffer_.id(),
                  texture_.id(), k, triangles_.id(), points_.id(), clampCount_.id(), pointsPerSide,
                  l.layers);
  }
  for (GLuint b = 1; b < GLuint(kReflectedChannels); ++b) glDisablei(GL_BLEND, b);
  for (int c = 0; c < kReflectedChannels; ++c)
    glNamedFramebufferTextureLayer(framebuffer_.id(), GL_COLOR_ATTACHMENT0 + GLenum(c), 0, 0, 0);
  if (l.spread) {
    // Every channel alike: the drift sums stay the light's own rays' (their ratio the mean).
    float heights[kMaxReflectedLayers] = {};
    for (int k = 0; k < l.layers; ++k) heights[k] = static_cast<float>(l.height[k]);
    for (const glkit::Texture& view : channelViews_)
      spread_.draw(frame, textures,
                   {view.id(), l.resolution, l.layers, heights, l.cell, l.windowSize,
                    reflectedLandingJacobian(sun),
                    reflectedSunDiscCovariance(
                        sun, 0.5 * glm::radians(double(frame.sun.angularDiameterDegrees)))});
  }
  glGenerateTextureMipmap(texture_.id());
  work::noteClear("reflected_caustics.mipmaps", levelBytes / 3);
}

void ReflectedFieldPass::release() {
  for (glkit::Texture& v : channelViews_) v.reset();
  texture_.reset();
  spread_.ensure(false, 0, 0);
  textureResolution_ = textureLayers_ = 0;
  gridPoints_.reset();
}

std::uint64_t ReflectedFieldPass::allocatedBytes() const {
  return textureBytes(texture_.id(), 4) + bufferBytes(gridPoints_.buffer()) +
         spread_.allocatedBytes();
}

}  // namespace postfx::detail
