#pragma once
// The landing spread of a grid-rasterised irradiance field (the wavefront area ratio's window,
// the reflected light's layers): each layer blurred by the Gaussian of where its light lands
// about where the grid put it, distance^2 (J S J^T + the sun disc's), S the slopes inside the
// grid's cells (read from the water texture, tile_irradiance_spread.comp) and J how a slope moves
// the landing per metre of distance (refraction's or reflection's). Separable, rows then
// columns (wavefront_area_ratio_spread.comp), through a copy of level 0.
#include <epoxy/gl.h>

#include <cstdint>
#include <string>

#include <glkit/handle.h>
#include <glkit/program.h>
#include <postfx/postfx.h>
#include <glm/glm.hpp>

#include "core/validation.h"
#include "seabed_caustics/cell_slope_statistics.h"

namespace postfx::detail {

struct LayerSpreadDesc {
  GLuint texture = 0;  // the R32F array to blur in place (level 0)
  int resolution = 0, layers = 0;
  const float* distances = nullptr;  // per layer: metres from the water (depth or height)
  double cell = 0.0;                 // the grid's spacing (m)
  double windowSize = 0.0;           // the texture's side (m)
  glm::dvec4 jacobian{
      0.0};  // d(landing offset per metre) / d(slopes), landingDriftJacobian's packing
  glm::dvec3 discCovariance{0.0};  // the sun disc's landing covariance per metre^2 (xx, xz, zz)
};

class LayerSpread {
 public:
  // `label`: the owning pass's name, for the debugger labels.
  Result init(const std::string& defines, const std::string& label, std::string& error);
  // Holds (or frees, when !on) the copy and the statistics for `resolution` x `layers`.
  void ensure(bool on, int resolution, int layers);
  bool allocated() const { return bool(rows_); }
  std::uint64_t allocatedBytes() const;
  // Records the spread. Expects the water texture bound on its unit; binds SSBO
  // POSTFX_STORAGE_TILE_SPREAD, texture unit POSTFX_UNIT_TILE_IRRADIANCE (its sampler unbound),
  // image unit POSTFX_IMAGE_TILE_IRRADIANCE.
  void draw(const FrameDesc& frame, const ValidatedTextures& textures, const LayerSpreadDesc& d);

 private:
  CellSlopeStatistics statistics_;
  glkit::Program blur_;
  glkit::Texture rows_;  // level 0 of every layer, blurred along rows
  std::string label_;
  std::string stepName_;  // "<pass>.spread", the work account's
};

// Bytes LayerSpread::ensure(true, resolution, layers) allocates.
std::uint64_t layerSpreadBytes(int resolution, int layers);

}  // namespace postfx::detail
