#include "seabed_caustics/grid_layer_draw.h"

#include <algorithm>
#include <cmath>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "core/work_account.h"

namespace postfx::detail {

void setGridDrawUniforms(GLuint triangles, GLuint points, float maxIrradiance, int pointsPerSide,
                         int texels, float pointRatio) {
  for (GLuint program : {triangles, points}) {
    glProgramUniform1f(program, 8, maxIrradiance);
    glProgramUniform1i(program, 9, pointsPerSide);
    glProgramUniform2f(program, 10, static_cast<float>(texels), pointRatio);
  }
}

void drawGridLayer(const GridStepNames& names, GLuint framebuffer, GLuint texture, int layer,
                   GLuint triangles, GLuint points, GLuint clampCount, int pointsPerSide,
                   int channelStride) {
  const int cells = pointsPerSide - 1;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_CLAMP_COUNT, clampCount);
  glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT0, texture, 0, layer);
  if (channelStride > 0) {
    glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT1, texture, 0,
                                   layer + channelStride);
    glNamedFramebufferTextureLayer(framebuffer, GL_COLOR_ATTACHMENT2, texture, 0,
                                   layer + 2 * channelStride);
  }
  // wavefront_area_ratio.vert per vertex: its grid point (position, transmittance: two texels;
  // a third with the drift); wavefront_area_ratio_points.vert per triangle: its three points.
  // Neither fragment stage fetches; both count the flux the clamp removes, two atomics at most
  // per fragment where it cuts (a bound: none where the light stays under it).
  const double perPoint = channelStride > 0 ? 3.0 : 2.0;
  const std::uint64_t gridBytes =
      std::uint64_t(pointsPerSide) * pointsPerSide * std::uint64_t(perPoint) * 16;
  glUseProgram(triangles);
  const StageWork clamp{0.0, 2.0, true};
  work::drawArrays({names.triangles, {perPoint, 0.0}, clamp, {Traffic::readBytes(gridBytes)}},
                   GL_TRIANGLE_STRIP, 0, 2 * pointsPerSide, cells);
  glUseProgram(points);
  work::drawArrays({names.points, {3.0 * perPoint, 0.0}, clamp, {Traffic::readBytes(gridBytes)}},
                   GL_POINTS, 0, 2 * cells * cells);
}

void cascadeGridUniforms(const WaterSurface& water, const glm::dvec2& gridOrigin, double cell,
                         int texelsPerSide, glm::vec4 (&out)[kMaxCascades]) {
  for (int c = 0; c < water.cascadeCount && c < kMaxCascades; ++c) {
    const double tile = water.tileSize[c];
    const glm::dvec2 fromOrigin = gridOrigin - water.origin;
    const double lod = std::max(0.0, std::log2(cell * texelsPerSide / tile));
    out[c] = glm::vec4(tileFraction(fromOrigin.x, tile), tileFraction(fromOrigin.y, tile),
                       cell / tile, lod);
  }
}

}  // namespace postfx::detail
