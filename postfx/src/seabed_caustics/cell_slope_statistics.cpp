#include "seabed_caustics/cell_slope_statistics.h"

#include <algorithm>

#include "core/gl_sizes.h"
#include "core/shader_library.h"
#include "core/shared_math.h"
#include "seabed_caustics/tile_irradiance_pass.h"

namespace postfx::detail {

Result CellSlopeStatistics::init(const std::string& defines, const std::string& label,
                                 std::string& error) {
  label_ = label + ".spread_statistics";
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
  for (int c = 0; c < cascades; ++c)
    cellsPerTile[c] = static_cast<float>(std::min(water.tileSize[c] / cell, double(texelsPerSide)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, POSTFX_STORAGE_TILE_SPREAD, buffer_.id());
  glProgramUniform4fv(program_.id(), 0, 1, &cellsPerTile.x);
  glUseProgram(program_.id());
  glDispatchCompute(static_cast<GLuint>(cascades), static_cast<GLuint>(shared::TILE_SPREAD_PARTS),
                    1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace postfx::detail
