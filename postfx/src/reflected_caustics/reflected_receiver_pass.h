#pragma once
// Reflected caustics landing on the view's depth (ReflectedLanding::ViewDepth), per view: every
// water grid point of the window mirrors the sun and its ray is followed through the view's
// G-buffer depth to the receiver it meets (reflected_receiver_rays.comp); the grid's triangles
// are then drawn where they landed, each with its flux over its area there, into a plugin-owned
// GL_R32F light target of the view's size (flat water's mirror light on the receiver; folds
// summed by the blend, sub-pixel triangles as bilinear points). Exact at every receiver height
// and orientation the view shows (no height layers), at the price of one march per grid point
// per view; receivers the view does not see cannot be lit, and occluders the view does not see
// do not shade.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"
#include "reflected_caustics/reflected_layout.h"
#include "seabed_caustics/cell_slope_statistics.h"
#include "seabed_caustics/grid_point_buffer.h"

namespace postfx::detail {

struct SeabedInputs;

class ReflectedReceiverPass {
 public:
  Result init(const std::string& defines, std::string& error);
  bool ready() const { return rays_.id() != 0; }

  // Allocates the grid points for `frame`'s settings and a light target of width x height
  // (the G-buffer's: every view fits); OutOfMemory with a message when the driver could not.
  Result reserve(const FrameDesc& frame, int width, int height, std::string& error);
  // Records the view's receivers' light for `frame`'s camera into texture()'s view-sized
  // corner. Expects CausticsPass::bindState's state (block, G-buffer, water and shadow units,
  // blending ONE, ONE on buffer 0); binds its own framebuffer, viewport, programs, vertex
  // array, SSBO binding and grid-point unit, and enables GL_PROGRAM_POINT_SIZE (the caller's
  // guard restores).
  void draw(const FrameDesc& frame, const ValidatedTextures& textures, const ReflectedLayout& l,
            const SeabedInputs& inputs);
  void release();

  GLuint texture() const { return light_.id(); }

  // The water grids that light the view: the window's (layout l's: its side and cells), then
  // one kOuterScale times wider with as many cells around it, the window its hole: far water
  // lights high and far receivers with coarser cells, the near water the waterline with fine
  // ones. The outer grid's square is where the pattern reaches.
  struct Grid {
    glm::dvec2 origin{0.0};  // world xz of grid point (0, 0)
    double cell = 0.0;       // m
    int cells = 0;           // per side
  };
  struct Grids {
    Grid level[2];
  };
  static constexpr double kOuterScale = 4.0;
  static Grids grids(const ReflectedLayout& l);
  std::uint64_t allocatedBytes() const;

 private:
  glkit::Program rays_, triangles_, points_;
  glkit::Framebuffer framebuffer_;
  glkit::VertexArray vertexArray_;
  glkit::Texture light_;
  int width_ = 0, height_ = 0;
  void drawGrid(const FrameDesc& frame, const ValidatedTextures& textures, const Grid& grid,
                int index, const glm::vec4& hole, const SeabedInputs& inputs);

  GridPointBuffer gridPoints_;  // each grid's in turn
  CellSlopeStatistics slopes_;
};

}  // namespace postfx::detail
