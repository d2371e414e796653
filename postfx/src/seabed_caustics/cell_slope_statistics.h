#pragma once
// The slope statistics inside a water grid's cells, per cascade (tile_irradiance_spread.comp):
// the slopes a grid of that spacing does not resolve, read from the host's water texture itself.
// Written into an SSBO at POSTFX_STORAGE_TILE_SPREAD for the shaders that spread the grid's
// light by them (tile_irradiance_spread_statistics.glsl's tileCellSlopes): the layer spread's
// blur and the reflected rays landing on the view's depth.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>

#include "core/validation.h"

namespace postfx::detail {

class CellSlopeStatistics {
 public:
  // `label`: the owning pass's name, for the debugger labels.
  Result init(const std::string& defines, const std::string& label, std::string& error);
  // Holds (or frees, when !on) the statistics' buffer.
  void ensure(bool on);
  std::uint64_t allocatedBytes() const;
  // Records the statistics of `frame`'s water for grid spacing `cell` (m) and leaves their
  // buffer bound at POSTFX_STORAGE_TILE_SPREAD. Expects the water texture bound on its unit.
  void measure(const FrameDesc& frame, const ValidatedTextures& textures, double cell);

  // tile_irradiance_spread.comp's water fetches for one cascade of `points` grid cells per tile
  // side on a water texture `waterSide` texels wide: up to TILE_SPREAD_SAMPLE_CELLS^2 of its
  // cells, round(texels per cell)^2 texels each (at most TILE_SPREAD_MAX_CELL_TEXELS^2), shared by
  // its TILE_SPREAD_PARTS x 256 invocations. Also the tile irradiance's own statistics.
  static double cascadeFetches(double points, int waterSide);

 private:
  glkit::Program program_;
  glkit::Buffer buffer_;
  std::string label_;
  std::string stepName_;  // "<pass>.spread_statistics", the work account's
};

}  // namespace postfx::detail
