#pragma once
// The reflected light field (Feature::ReflectedCaustics): per height layer, a compute step
// mirrors every water grid point's sun ray onto the layer (reflected_light_vertices.comp), and
// the wavefront area ratio's own triangle and point draws add up the beam area over the landing
// area, folds summed, into a layer of a plugin-owned GL_R32F 2D array with mips (footprint-
// filtered lookups); with it, that light times its rays' drift per metre of rise (x and z), in
// layers of their own, so that a receiver of any orientation and height between the layers gets
// what its rays deliver (postfx_reflected_caustics.h). Layer c * layers + k holds channel c
// (light, drift x, drift z) of height layer k. Drawn per view: its window follows the view's
// camera, as the refracted window's does. Why a grid mesh and not the periodic tile field the
// seabed uses: a mirror deviates light by twice the slope (refraction by a quarter of it), so
// reflected light is sharp and focused within metres of the water, and the tile field's product of
// per-cascade fields (each cascade alone) is far from the light their summed slopes mirror.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"
#include "reflected_caustics/reflected_layout.h"
#include "seabed_caustics/grid_point_buffer.h"
#include "seabed_caustics/layer_spread.h"

namespace postfx::detail {

struct SeabedInputs;

class ReflectedFieldPass {
 public:
  Result init(const std::string& defines, std::string& error);
  bool ready() const { return triangles_.id() != 0; }

  // Allocates the layers and grid points for `frame`'s settings (before any pass adds light);
  // OutOfMemory with a message when the driver could not.
  Result reserve(const FrameDesc& frame, std::string& error);
  // Records the field for `frame`'s camera: clears and fills every layer, then its mips.
  // Expects the water texture bound on its unit with its sampler (CausticsPass::bindState);
  // binds its own framebuffer, viewport, programs, vertex array, SSBO bindings 0, texture unit
  // POSTFX_UNIT_GRID_POINTS, and enables GL_PROGRAM_POINT_SIZE (the caller's guard restores).
  void draw(const FrameDesc& frame, const ValidatedTextures& textures, const SeabedInputs& inputs);
  // Frees the field (a frame without the pass holds none of its memory).
  void release();

  GLuint texture() const { return texture_.id(); }
  const ReflectedLayout& layout() const { return layout_; }
  std::uint64_t allocatedBytes() const;

 private:
  glkit::Program vertices_, triangles_, points_;
  glkit::Framebuffer framebuffer_;
  glkit::VertexArray vertexArray_;
  glkit::Texture texture_;
  glkit::Texture channelViews_[kReflectedChannels];  // texture_'s layers of one channel each
  glkit::Buffer clampCount_;  // the draws count what the clamp removes; nobody reads it here
  int textureResolution_ = 0, textureLayers_ = 0;
  GridPointBuffer gridPoints_;
  LayerSpread spread_;
  ReflectedLayout layout_{};
};

}  // namespace postfx::detail
