#include "seabed_caustics/cell_slope_statistics.h"

#include <algorithm>
#include <cmath>

#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "core/work_account.h"
#include "seabed_caustics/tile_irradiance_pass.h"

namespace postfx::detail {

Result CellSlopeStatistics::init(const std::string& defines, const std::string& label,
                                 std::string& error) {
  label_ = label + ".spread_statistics";
  stepName_ = label_.substr(label_.find('.') + 1);
  return buildPrograms(
      defines,
      {{program_,
        label_,
        {{GL_COMPUTE_SHADER, "postfx/seabed_caustics/tile_irradiance_spread.comp"}}}},
      error);
}

void CellSlopeStatistics::ensure(bool on) {
  if (on == bool(buffer_)) return;
  buffer_.reset();
  if (on)
    buffer_ = glkit::createBuffer(GLsizeiptr(tileSpreadStatisticsBytes()), nullptr,
                                  GL_DYNAMIC_STORAGE_BIT, label_.c_str());
}

std::uint64_t CellSlopeStatistics::allocatedBytes() const {
  return bufferBytes(buffer_.id());
}

void CellSlopeStatistics::measure(const FrameDesc& frame, const ValidatedTextures& textures,
                                  double cell) {
  const WaterSurface& water = frame.water;
  const int cascades = std::min(water.cascadeCount, kMaxCascades);
  // Each cascade's cells per tile: the tile over the grid spacing (the grid's water lookups are
  // filtered to that cell).
  const int texelsPerSide = std::max(textures.water.width, textures.water.height);
  glm::vec4 cellsPerTile(1.0f);
  double fetches = 0.0;
  for (int c = 0; c < cascades; ++c) {
    cellsPerTile[c] = static_cast<float>(std::min(water.tileSize[c] / cell, double(texelsPerSide)));
    fetches += cascadeFetches(cellsPerTile[c], texelsPerSide);
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_TILE_SPREAD, buffer_.id());
  glProgramUniform4fv(program_.id(), 0, 1, &cellsPerTile.x);
  glUseProgram(program_.id());
  const double invocations = double(std::max(cascades, 1)) * shared::TILE_SPREAD_PARTS * 256.0;
  work::dispatchCompute({stepName_.c_str(),
                         {},
                         {fetches * shared::TILE_SPREAD_PARTS * 256.0 / invocations, 0.0},
                         {Traffic::readBytes(static_cast<std::uint64_t>(fetches) *
                                             shared::TILE_SPREAD_PARTS * 256 * 8)}},
                        static_cast<GLuint>(cascades),
                        static_cast<GLuint>(shared::TILE_SPREAD_PARTS), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

double CellSlopeStatistics::cascadeFetches(double points, int waterSide) {
  points = std::max(points, 1.0);
  const int perCell = std::clamp(int(std::lround(double(waterSide) / points)), 1,
                                 shared::TILE_SPREAD_MAX_CELL_TEXELS);
  const int sampled = std::min(int(points), shared::TILE_SPREAD_SAMPLE_CELLS);
  return double(sampled) * sampled * perCell * perCell /
         (double(shared::TILE_SPREAD_PARTS) * 256.0);
}

}  // namespace postfx::detail
