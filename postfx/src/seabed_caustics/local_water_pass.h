#pragma once
// The local water regions' light (Feature::LocalWater), once per frame for every view: per region,
// per depth layer, its grid refracted onto the layer (local_water_vertices.comp) and drawn by the
// wavefront area ratio's own triangle and point draws into its layers of one plugin-owned GL_R32F
// 2D array with mips (a second set of layers in Add mode: the same grid without the region's
// heights).
// Then, per view, bind() hands the textures and the view's block to the caustics and god rays.
// Nothing is allocated before a frame gives a region.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"
#include "seabed_caustics/grid_point_buffer.h"
#include "seabed_caustics/local_water_layout.h"

namespace postfx::detail {

class LocalWaterPass {
 public:
  Result init(const std::string& defines, std::string& error);
  bool ready() const { return vertices_.id() != 0; }

  // Allocates this frame's layers and grid points before any pass adds light: OutOfMemory with
  // a message when the driver could not.
  Result reserve(const FrameDesc& frame, std::string& error);
  // Records every region's layers. Expects the caustics pass's state (blend ONE, ONE on draw
  // buffer 0) with the water texture on its unit; binds its own framebuffer, viewport, programs,
  // vertex array, SSBO binding 0, texture units POSTFX_UNIT_LOCAL_SURFACE and
  // POSTFX_UNIT_GRID_POINTS, and enables GL_PROGRAM_POINT_SIZE.
  void draw(const FrameDesc& frame, const ValidatedTextures& textures);
  // Binds the regions' layers on unit POSTFX_UNIT_LOCAL_WATER and uploads `frame`'s block
  // (its camera's) at POSTFX_LOCAL_WATER_BLOCK_BINDING, for the passes of one view. Called for
  // every view that draws while the context has the feature, regions or not: the shaders read
  // the block's count.
  // `regions` false: a block of count 0 (the frame's regions are not drawn).
  void bind(const FrameDesc& frame, bool regions);

  // Frees every region's layers and the grid points (a frame without regions holds nothing).
  void release();
  // What its textures and buffers hold now, asked of GL (0 before the first region).
  std::uint64_t allocatedBytes() const;

 private:
  void ensureTexture(const LocalWaterTexture& layout);
  void drawRegion(const FrameDesc& frame, const ValidatedTextures& textures, int r, int firstLayer);

  glkit::Program vertices_, triangles_, points_;
  glkit::Framebuffer framebuffer_;
  glkit::VertexArray vertexArray_;
  glkit::Sampler surfaceSampler_, lookupSampler_;
  glkit::Buffer block_;
  glkit::Buffer clampCount_;  // the draws count what maxIrradiance removes; not reported here
  // Every region's layers, one after another (LocalWaterTexture).
  glkit::Texture texture_;
  int textureSide_ = 0, textureLayers_ = 0;
  GridPointBuffer gridPoints_;  // the largest region's, reused by every region and layer
};

}  // namespace postfx::detail
