#pragma once
// The wavefront area ratio's two draws of a computed grid (grid_point_buffer.h) into one layer of
// an irradiance array, shared by the refracted window, the local water regions and the reflected
// light: one instanced strip of triangles per row, then a point per triangle too small to
// rasterise; and the per-cascade lookups of the water under a grid.
#include <epoxy/gl.h>

#include <glm/glm.hpp>

#include <postfx/postfx.h>

namespace postfx::detail {

// The uniforms the two draws share (wavefront_area_ratio_common.glsl): the clamp, the grid's
// points per side, the layer's texels per side and the area ratio above which a triangle is
// drawn as a point.
void setGridDrawUniforms(GLuint triangles, GLuint points, float maxIrradiance, int pointsPerSide,
                         int texels, float pointRatio);

// Draws the grid (`pointsPerSide`^2 points, computed) into `layer` of `texture` through
// `framebuffer`, counting the clamp's removed flux in `clampCount`. Expects the grid points'
// view on POSTFX_UNIT_GRID_POINTS, blend ONE, ONE, the viewport and vertex array set. With
// `channelStride` > 0 the programs write two more channels (POSTFX_GRID_DRIFT), into layers
// layer + channelStride and layer + 2 channelStride on attachments 1 and 2 (the framebuffer's
// draw buffers set to all three).
// `names`: the two draws' work-account steps ("<pass>.triangles", "<pass>.points").
struct GridStepNames {
  const char* triangles;
  const char* points;
};
void drawGridLayer(const GridStepNames& names, GLuint framebuffer, GLuint texture, int layer,
                   GLuint triangles, GLuint points, GLuint clampCount, int pointsPerSide,
                   int channelStride = 0);

// Per cascade of `water`: the uv of the grid point at world `gridOrigin` (reduced modulo the tile
// in double), the uv per grid `cell`, and the mip level whose texel matches the cell (finer
// ripples cannot be carried by the grid and would alias into false lines), for a water texture
// of `texelsPerSide`.
void cascadeGridUniforms(const WaterSurface& water, const glm::dvec2& gridOrigin, double cell,
                         int texelsPerSide, glm::vec4 (&out)[kMaxCascades]);

}  // namespace postfx::detail
