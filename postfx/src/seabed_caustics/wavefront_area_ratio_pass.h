#pragma once
// The WavefrontAreaRatio model's irradiance pass [4]. Per depth layer: a compute step
// refracts every surface grid point onto the receiver (into a buffer); one instanced strip
// draw rasterises the refracted triangles, blended additively into a layer of a plugin-owned
// GL_R32F 2D array; a point draw deposits the flux of the triangles too small to rasterise
// without noise (under half a texel), split over its four nearest texels by bilinear weights.
// Then the landing spread (wavefront_area_ratio_spread.comp): each layer blurred by what the
// grid cannot carry, the slopes inside its cells and the sun's disc, as the tile field is.
// Only built with Feature::WavefrontAreaRatio.
// Why a rasterised mesh rather than splatting photons: each triangle carries exactly the flux
// of its piece of the beam, so the result is noise-free at any grid size and folds sum for free
// in the blender. Why the area ratio in the fragment stage: it needs all three vertices, and
// screen derivatives of an affine varying give the triangle's exact ratio without a geometry
// shader (slow on many GPUs) or a buffer of per-triangle values.
// The clamp count is read back through a ring of small buffers with fences, polled, never
// waited on (like the timers).
#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/gpu_timers.h"
#include "core/validation.h"
#include "seabed_caustics/grid_point_buffer.h"
#include "seabed_caustics/layer_spread.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {

class WavefrontAreaRatioPass {
 public:
  Result init(const std::string& defines, std::string& error);
  bool ready() const { return triangles_.id() != 0; }

  // Reads every clamp count that has completed, oldest first. Returns the newest fraction
  // read, or a negative value when none completed.
  double pollClampCounts();
  // Allocates this frame's irradiance layers and grid points (before any pass adds light);
  // OutOfMemory with a message when the driver could not.
  Result reserve(const FrameDesc& frame, std::string& error);
  // Places the window around `frame`'s camera (reserve() did for its frame): each view of a
  // frame draws its own window into the one texture, which reserve() sized for all.
  void place(const FrameDesc& frame);
  // Records the pass: clears and fills every layer. Expects the caustics pass's fixed-function
  // state (blend ONE, ONE on draw buffer 0, no cull/scissor) and the water texture bound on
  // its unit; binds its own framebuffer, viewport, programs, vertex array, SSBO bindings 0 and
  // 2, image unit 0, texture unit POSTFX_UNIT_GRID_POINTS, and enables GL_PROGRAM_POINT_SIZE.
  void draw(const FrameDesc& frame, const ValidatedTextures& textures);

  GLuint texture() const { return texture_.id(); }
  const WavefrontAreaRatioLayout& layout() const { return layout_; }
  // What its texture and grid-point buffer hold now, asked of GL (0 before the first frame).
  std::uint64_t allocatedBytes() const;

 private:
  void ensureTexture(int resolution, int layers, bool spread);

  glkit::Program vertices_, triangles_, points_;
  glkit::Framebuffer framebuffer_;
  glkit::VertexArray vertexArray_;
  glkit::Texture texture_;
  int textureResolution_ = 0, textureLayers_ = 0;
  LayerSpread spread_;  // the landing spread (with it on: layout_.spread)
  GridPointBuffer gridPoints_;
  WavefrontAreaRatioLayout layout_{};
  struct ClampSlot {
    glkit::Buffer buffer;
    glkit::Fence fence;
    double flatFlux = 1.0;  // texels x layers of the frame: the fraction's denominator
    std::uint64_t frame = 0;
  };
  std::array<ClampSlot, kTimerRingDepth> clampSlots_{};
  std::uint64_t frame_ = 0;
};

}  // namespace postfx::detail
