#include "seabed_caustics/wavefront_area_ratio_pass.h"

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

#include "core/block_check.h"
#include "core/frame_geometry.h"
#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/caustics_constants.h"
#include "seabed_caustics/grid_layer_draw.h"
#include "seabed_caustics/tile_irradiance_pass.h"

namespace postfx::detail {

Result WavefrontAreaRatioPass::init(const std::string& defines, std::string& error) {
  Result r = buildPrograms(
      defines,
      {{vertices_,
        "postfx.wavefront_area_ratio.grid",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_vertices.comp"}}},
       {triangles_,
        "postfx.wavefront_area_ratio.triangles",
        {{GL_VERTEX_SHADER, "postfx/seabed_caustics/wavefront_area_ratio.vert"},
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/wavefront_area_ratio.frag"}}},
       {points_,
        "postfx.wavefront_area_ratio.points",
        {{GL_VERTEX_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_points.vert"},
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_points.frag"}}}},
      error);
  if (r != Result::Ok) return r;
  r = spread_.init(defines, "postfx.wavefront_area_ratio", error);
  if (r != Result::Ok) return r;
  framebuffer_ = glkit::createFramebuffer("postfx.wavefront_area_ratio.framebuffer");
  vertexArray_ = glkit::createVertexArray("postfx.wavefront_area_ratio.vao");
  for (ClampSlot& slot : clampSlots_)
    slot.buffer = glkit::createBuffer(2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT,
                                      "postfx.wavefront_area_ratio.clamp_count");
  return Result::Ok;
}

void WavefrontAreaRatioPass::ensureTexture(int resolution, int layers, bool spread) {
  if (!(texture_ && textureResolution_ == resolution && textureLayers_ == layers)) {
    // The old size goes first: never two of them allocated at once.
    texture_.reset();
    spread_.ensure(false, 0, 0);
    texture_ = glkit::createTexture(GL_TEXTURE_2D_ARRAY, "postfx.wavefront_area_ratio");
    // R32F: additive sums of many triangles stay exact well past R16F's 11 bits. With its mip
    // chain: the lookup filters a pixel's footprint (irradiance is linear, so a mip level is the
    // mean light over its texels), where point lookups at level 0 aliased into sparkle and
    // flicker.
    glTextureStorage3D(texture_.id(), wavefrontAreaRatioMipLevels(resolution), GL_R32F, resolution,
                       resolution, layers);
    textureResolution_ = resolution;
    textureLayers_ = layers;
  }
  spread_.ensure(spread, resolution, layers);
}

std::uint64_t WavefrontAreaRatioPass::allocatedBytes() const {
  return textureBytes(texture_.id(), 4) + bufferBytes(gridPoints_.buffer()) +  // R32F
         spread_.allocatedBytes();
}

double WavefrontAreaRatioPass::pollClampCounts() {
  // Oldest first, so the value returned is the newest one completed.
  double newest = -1.0;
  for (;;) {
    ClampSlot* oldest = nullptr;
    for (ClampSlot& s : clampSlots_)
      if (s.fence && (oldest == nullptr || s.frame < oldest->frame)) oldest = &s;
    if (oldest == nullptr) break;
    ClampSlot& slot = *oldest;
    const GLenum status = glClientWaitSync(slot.fence.id(), 0, 0);  // timeout 0: a poll
    if (status != GL_ALREADY_SIGNALED && status != GL_CONDITION_SATISFIED) break;
    GLuint words[2] = {0, 0};
    glGetNamedBufferSubData(slot.buffer.id(), 0, sizeof(words), words);
    const double units = static_cast<double>(words[0]) + 4294967296.0 * words[1];
    newest = units / 256.0 / slot.flatFlux;
    slot.fence.reset();
  }
  return newest;
}

void WavefrontAreaRatioPass::place(const FrameDesc& frame) {
  layout_ = wavefrontAreaRatioLayout(frame);
}

Result WavefrontAreaRatioPass::reserve(const FrameDesc& frame, std::string& error) {
  place(frame);
  ensureTexture(layout_.resolution, layout_.layers, layout_.spread);
  // Reused by every layer in turn.
  const std::uint64_t side = std::uint64_t(layout_.cells) + 1;
  const bool points = gridPoints_.ensure(side * side, "postfx.wavefront_area_ratio.grid_points");
  // Storage that failed (GL_OUT_OF_MEMORY) leaves the texture without levels and the buffer
  // without bytes: found here, before anything is drawn.
  if (glkit::storedWidth(texture_) != layout_.resolution || !points) {
    error = "caustics: the driver could not allocate the irradiance layers (gridResolution " +
            std::to_string(layout_.resolution) + ")";
    return Result::OutOfMemory;
  }
  return Result::Ok;
}

void WavefrontAreaRatioPass::draw(const FrameDesc& frame, const ValidatedTextures& textures) {
  const WavefrontAreaRatioLayout& l = layout_;
  const float zero = 0.0f;
  glClearTexImage(texture_.id(), 0, GL_RED, GL_FLOAT, &zero);
  const std::uint64_t layerBytes = std::uint64_t(l.resolution) * l.resolution * 4;  // R32F
  work::noteClear("wavefront_area_ratio.clear", layerBytes * std::uint64_t(l.layers));

  // A slot still pending after a whole ring of frames is dropped rather than waited for.
  ClampSlot& slot = clampSlots_[frame_ % clampSlots_.size()];
  slot.fence.reset();
  slot.frame = frame_++;
  slot.flatFlux = static_cast<double>(l.resolution) * l.resolution * l.layers;
  const GLuint zeros[2] = {0, 0};
  glNamedBufferSubData(slot.buffer.id(), 0, sizeof(zeros), zeros);

  const int pointsPerSide = l.cells + 1;
  const WaterSurface& water = frame.water;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  const double flatT = shared::fresnelTransmittance(static_cast<float>(sun.y), water.ior);
  const double texelsPerMetre = l.resolution / l.windowSize;
  // Triangles whose refracted area is under half a texel go to the point draw: their area ratio
  // exceeds (nominal beam area of a triangle, half a cell squared) / (1/2 texel). Rasterised,
  // such a triangle covers 0, 1 or 2 texel centres as it moves (a quarter texel was the bound
  // before: with time running the physical model then changed 0.207 per frame against 0.168
  // now, ocean_sample report --only stability --quick). Half a texel stays under flat water's
  // own triangles (0.78 texel), which keep their exact rasterised ratio of 1.
  const double cellTexels = l.cell * texelsPerMetre;
  const float pointRatio = static_cast<float>(0.5 * cellTexels * cellTexels / 0.5);
  const GLuint compute = vertices_.id();
  glProgramUniform1i(compute, 4, water.cascadeCount);
  glProgramUniform4f(compute, 6, static_cast<float>(sun.x), static_cast<float>(sun.y),
                     static_cast<float>(sun.z), water.ior);
  glProgramUniform4f(compute, 7, saturatedFloat(flatT > 0.0 ? 1.0 / flatT : 0.0),
                     static_cast<float>(texelsPerMetre), 0.0f, 0.0f);
  glProgramUniform1i(compute, 9, pointsPerSide);
  setGridDrawUniforms(triangles_.id(), points_.id(), frame.caustics.maxIrradiance, pointsPerSide,
                      l.resolution, pointRatio);

  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glViewportIndexedf(0, 0.0f, 0.0f, static_cast<float>(l.resolution),
                     static_cast<float>(l.resolution));
  glBindVertexArray(vertexArray_.id());
  glEnable(GL_PROGRAM_POINT_SIZE);
  glBindTextureUnit(POSTFX_UNIT_GRID_POINTS, gridPoints_.view());
  const int texelsPerSide = std::max(textures.water.width, textures.water.height);
  const GLuint groups = static_cast<GLuint>((pointsPerSide + 15) / 16);
  for (int k = 0; k < l.layers; ++k) {
    glm::vec4 cascades[kMaxCascades];
    cascadeGridUniforms(water, l.gridOrigin[k], l.cell, texelsPerSide, cascades);
    glProgramUniform4fv(compute, 0, water.cascadeCount, &cascades[0].x);
    const glm::dvec2 gridLocal = l.gridOrigin[k] - l.windowOrigin;
    glProgramUniform4f(compute, 5, static_cast<float>(gridLocal.x), static_cast<float>(gridLocal.y),
                       static_cast<float>(l.cell), static_cast<float>(l.depth[k]));
    glUseProgram(compute);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_GRID_POINTS, gridPoints_.buffer());
    // wavefront_area_ratio_vertices.comp per grid point: each cascade's water (grid_water.glsl).
    const double points = double(pointsPerSide) * pointsPerSide;
    work::dispatchCompute(
        {"wavefront_area_ratio.vertices",
         {},
         {perInvocation(water.cascadeCount, points, groups * groups * 256.0)},
         {Traffic::read(water.texture.texture), Traffic::writeBuffer(gridPoints_.buffer())}},
        groups, groups, 1);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);

    drawGridLayer({"wavefront_area_ratio.triangles", "wavefront_area_ratio.points"},
                  framebuffer_.id(), texture_.id(), k, triangles_.id(), points_.id(),
                  slot.buffer.id(), pointsPerSide);
  }
  // The spread before the last layer is detached: dispatched after the detach, llvmpipe's
  // GL_TIME_ELAPSED query around the next pass (the tile field's, compute only) read 11,000 s
  // in every frame (Mesa 22.3); nothing else changes with the order.
  if (l.spread) {
    float depths[kMaxWavefrontAreaRatioLayers] = {};
    for (int k = 0; k < l.layers; ++k) depths[k] = static_cast<float>(l.depth[k]);
    spread_.draw(
        frame, textures,
        {texture_.id(), l.resolution, l.layers, depths, l.cell, l.windowSize,
         landingDriftJacobian(sun, water.ior),
         sunDiscLandingCovariance(sun, water.ior,
                                  0.5 * glm::radians(double(frame.sun.angularDiameterDegrees)))});
  }
  glNamedFramebufferTextureLayer(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0, 0);
  glGenerateTextureMipmap(texture_.id());
  // Each level read once and a third of it written again.
  work::noteClear("wavefront_area_ratio.mipmaps", layerBytes * std::uint64_t(l.layers) / 3);
  // The fragment atomics must land before the buffer is read back. (The irradiance itself is a
  // framebuffer write, ordered before later draws that sample it without a barrier.)
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  slot.fence = glkit::Fence(glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0));
}

}  // namespace postfx::detail
