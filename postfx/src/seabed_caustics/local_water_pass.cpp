#include "seabed_caustics/local_water_pass.h"

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

#include "core/block_check.h"
#include "core/frame_geometry.h"
#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/grid_layer_draw.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {

Result LocalWaterPass::init(const std::string& defines, std::string& error) {
  // The triangle and point draws are the wavefront area ratio's own: they read grid points in
  // texels, whatever placed them.
  const Result r = buildPrograms(
      defines,
      {{vertices_,
        "postfx.local_water.grid",
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/local_water_vertices.comp"}}},
       {triangles_,
        "postfx.local_water.triangles",
        {{GL_VERTEX_SHADER, "postfx/seabed_caustics/wavefront_area_ratio.vert"},
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/wavefront_area_ratio.frag"}}},
       {points_,
        "postfx.local_water.points",
        {{GL_VERTEX_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_points.vert"},
         {GL_FRAGMENT_SHADER, "postfx/seabed_caustics/wavefront_area_ratio_points.frag"}}}},
      error);
  if (r != Result::Ok) return r;
  framebuffer_ = glkit::createFramebuffer("postfx.local_water.framebuffer");
  vertexArray_ = glkit::createVertexArray("postfx.local_water.vao");
  // The host's surface: clamped at the rectangle's edge, level 0 (the grid is the resolution).
  surfaceSampler_ =
      glkit::createSampler(GL_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE, "postfx.sampler.local_surface");
  lookupSampler_ = glkit::createSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, GL_CLAMP_TO_EDGE,
                                        "postfx.sampler.local_water");
  block_ = glkit::createBuffer(sizeof(shared::LocalWaterBlock), nullptr, GL_DYNAMIC_STORAGE_BIT,
                               "postfx.local_water.block");
  clampCount_ = glkit::createBuffer(2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT,
                                    "postfx.local_water.clamp_count");
  return Result::Ok;
}

void LocalWaterPass::ensureTexture(const LocalWaterTexture& layout) {
  if (texture_ && textureSide_ == layout.side && textureLayers_ == layout.layers) return;
  texture_.reset();  // the old size goes first: never two allocated at once
  texture_ = glkit::createTexture(GL_TEXTURE_2D_ARRAY, "postfx.local_water.irradiance");
  // R32F with mips, as the window model's: exact additive sums, footprint-filtered lookups.
  glTextureStorage3D(texture_.id(), wavefrontAreaRatioMipLevels(layout.side), GL_R32F, layout.side,
                     layout.side, layout.layers);
  textureSide_ = layout.side;
  textureLayers_ = layout.layers;
}

Result LocalWaterPass::reserve(const FrameDesc& frame, std::string& error) {
  const LocalWaterTexture layout = localWaterTexture(frame);
  ensureTexture(layout);
  if (glkit::storedWidth(texture_) != layout.side) {
    textureSide_ = 0;
    error = "water.localWater: the driver could not allocate the regions' irradiance layers (" +
            std::to_string(layout.side) + " texels a side, " + std::to_string(layout.layers) +
            " layers)";
    return Result::OutOfMemory;
  }
  if (!gridPoints_.ensure(localWaterGridPoints(frame), "postfx.local_water.grid_points")) {
    error = "water.localWater: the driver could not allocate the grid points";
    return Result::OutOfMemory;
  }
  return Result::Ok;
}

void LocalWaterPass::draw(const FrameDesc& frame, const ValidatedTextures& textures) {
  glBindVertexArray(vertexArray_.id());
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, framebuffer_.id());
  glEnable(GL_PROGRAM_POINT_SIZE);
  glBindTextureUnit(POSTFX_UNIT_GRID_POINTS, gridPoints_.view());
  glBindSampler(POSTFX_UNIT_GRID_POINTS, 0);
  glBindSampler(POSTFX_UNIT_LOCAL_SURFACE, surfaceSampler_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_CLAMP_COUNT, clampCount_.id());
  const float zero = 0.0f;
  glClearTexImage(texture_.id(), 0, GL_RED, GL_FLOAT, &zero);
  const std::uint64_t levelBytes = textureBytes(texture_.id(), 4) * 3 / 4;  // R32F, level 0
  work::noteClear("local_water.clear", levelBytes);
  const LocalWaterTexture layout = localWaterTexture(frame);
  for (int r = 0; r < frame.water.localWaterCount; ++r)
    drawRegion(frame, textures, r, layout.firstLayer[r]);
  glNamedFramebufferTextureLayer(framebuffer_.id(), GL_COLOR_ATTACHMENT0, 0, 0, 0);
  glGenerateTextureMipmap(texture_.id());
  work::noteClear("local_water.mipmaps", levelBytes / 3);
}

void LocalWaterPass::drawRegion(const FrameDesc& frame, const ValidatedTextures& textures, int r,
                                int firstLayer) {
  const LocalWater& region = frame.water.localWater[r];
  const LocalWaterLayout l = localWaterLayout(region, frame);
  const WaterSurface& water = frame.water;
  glBindTextureUnit(POSTFX_UNIT_LOCAL_SURFACE, region.texture.texture);

  const glm::dvec2 axisV(-l.axisU.y, l.axisU.x);
  // Grid point (0, 0) half a cell beyond the edge: the points lie at the centres of cells of the
  // rectangle (of the host's texels, where its texture has gridResolution of them: the grid
  // then reads the texture's own values, where points on texel corners averaged four and
  // softened the light).
  const glm::dvec2 gridCorner = -l.half - 0.5 * l.cell;
  // The cascades beneath (Add mode), each at the mip level whose texel matches the grid
  // spacing: finer ripples cannot be carried by the grid and would alias into false caustics.
  const int cascades = l.add ? water.cascadeCount : 0;
  glm::vec4 cascadeGrid[kMaxCascades] = {}, cascadeStep[kMaxCascades] = {};
  const int texelsPerSide = std::max(textures.water.width, textures.water.height);
  const glm::dvec2 world0 =
      region.centre + gridCorner.x * l.axisU + gridCorner.y * axisV - water.origin;
  for (int c = 0; c < cascades; ++c) {
    const double tile = water.tileSize[c];
    const double lod =
        std::max(0.0, std::log2(std::min(l.cell.x, l.cell.y) * texelsPerSide / tile));
    cascadeGrid[c] =
        glm::vec4(tileFraction(world0.x, tile), tileFraction(world0.y, tile), float(lod), 0.0f);
    const glm::dvec2 stepI = l.axisU * l.cell.x / tile, stepJ = axisV * l.cell.y / tile;
    cascadeStep[c] = glm::vec4(stepI.x, stepI.y, stepJ.x, stepJ.y);
  }
  const GLuint compute = vertices_.id();
  if (cascades > 0) {
    glProgramUniform4fv(compute, 0, cascades, &cascadeGrid[0].x);
    glProgramUniform4fv(compute, 4, cascades, &cascadeStep[0].x);
  }
  glProgramUniform4f(compute, 9, float(gridCorner.x), float(gridCorner.y), float(l.cell.x),
                     float(l.cell.y));
  // Texture uv = (local + half) / size: grid point (0, 0) lies half a cell before uv 0.
  glProgramUniform4f(compute, 10, float(-0.5 / l.cells), float(-0.5 / l.cells),
                     float(1.0 / l.cells), float(1.0 / l.cells));
  const double flatT = shared::fresnelTransmittance(float(l.sunLocal.y), water.ior);
  glProgramUniform4f(compute, 11, float(l.sunLocal.x), float(l.sunLocal.y), float(l.sunLocal.z),
                     water.ior);
  glProgramUniform1i(compute, 14, l.pointsPerSide);
  glProgramUniform2f(compute, 15, float(l.axisU.x), float(l.axisU.y));
  // Triangles whose refracted area is under 0.35 texel go to the point draw (see
  // WavefrontAreaRatioPass::draw). One texel per cell: flat water's triangles are half a texel,
  // and must stay rasterised with their exact ratio of 1 (at half a texel, rounding sent some of
  // them to the points).
  const float pointRatio = 0.5f / 0.35f;
  setGridDrawUniforms(triangles_.id(), points_.id(), frame.caustics.maxIrradiance, l.pointsPerSide,
                      l.texels, pointRatio);
  glViewportIndexedf(0, 0.0f, 0.0f, float(l.texels), float(l.texels));
  const GLuint groups = static_cast<GLuint>((l.pointsPerSide + 15) / 16);
  for (int field = 0; field < (l.add ? 2 : 1); ++field) {
    // Field 0: the region's surface (with the cascades in Add mode); field 1: the cascades alone.
    glProgramUniform2i(compute, 8, cascades, field == 0 ? 1 : 0);
    for (int k = 0; k < l.layers; ++k) {
      const glm::dvec2 entryCorner = l.windowCorner + l.drift * l.depth[k];
      glProgramUniform4f(compute, 12, saturatedFloat(flatT > 0.0 ? 1.0 / flatT : 0.0),
                         float(l.depth[k]), float(1.0 / l.cell.x), float(1.0 / l.cell.y));
      glProgramUniform4f(compute, 13, float(entryCorner.x), float(entryCorner.y),
                         float(l.windowCorner.x), float(l.windowCorner.y));
      glUseProgram(compute);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_GRID_POINTS, gridPoints_.buffer());
      // local_water_vertices.comp per grid point: the cascades beneath (Add mode) and, for the
      // joint field, the region's own surface.
      const double points = double(l.pointsPerSide) * l.pointsPerSide;
      work::dispatchCompute(
          {"local_water.vertices",
           {},
           {perInvocation(cascades + (field == 0 ? 1 : 0), points, groups * groups * 256.0)},
           {Traffic::read(region.texture.texture),
            Traffic::read(cascades > 0 ? water.texture.texture : 0u),
            Traffic::writeBuffer(gridPoints_.buffer())}},
          groups, groups, 1);
      glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
      drawGridLayer({"local_water.triangles", "local_water.points"}, framebuffer_.id(),
                    texture_.id(), firstLayer + field * l.layers + k, triangles_.id(), points_.id(),
                    clampCount_.id(), l.pointsPerSide);
    }
  }
}

void LocalWaterPass::bind(const FrameDesc& frame, bool regions) {
  const shared::LocalWaterBlock block =
      regions ? buildLocalWaterBlock(frame) : shared::LocalWaterBlock{};
  glNamedBufferSubData(block_.id(), 0, sizeof(block), &block);
  glBindBufferBase(GL_UNIFORM_BUFFER, POSTFX_LOCAL_WATER_BLOCK_BINDING, block_.id());
  glBindTextureUnit(POSTFX_UNIT_LOCAL_WATER, regions ? texture_.id() : 0);
  glBindSampler(POSTFX_UNIT_LOCAL_WATER, lookupSampler_.id());
}

void LocalWaterPass::release() {
  texture_.reset();
  textureSide_ = textureLayers_ = 0;
  gridPoints_.reset();
}

std::uint64_t LocalWaterPass::allocatedBytes() const {
  return bufferBytes(gridPoints_.buffer()) + textureBytes(texture_.id(), 4);
}

}  // namespace postfx::detail
