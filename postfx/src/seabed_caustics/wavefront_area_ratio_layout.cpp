#include "seabed_caustics/wavefront_area_ratio_layout.h"

#include <algorithm>
#include <cmath>

#include <glkit/texture.h>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "seabed_caustics/layer_spread.h"
#include "seabed_caustics/tile_irradiance_pass.h"

namespace postfx::detail {

double wavefrontAreaRatioLayerDepth(int k, int layers, double maxDepth) {
  const double f = static_cast<double>(k + 1) / static_cast<double>(std::max(layers, 1));
  return maxDepth * f * f;
}

WavefrontAreaRatioLayout wavefrontAreaRatioLayout(const FrameDesc& frame) {
  const CausticsSettings& s = frame.caustics;
  WavefrontAreaRatioLayout l;
  l.resolution = s.gridResolution;
  l.layers = std::clamp(s.depthLayers, 1, kMaxWavefrontAreaRatioLayers);
  l.windowSize = s.windowSize;
  l.texel = l.windowSize / l.resolution;
  const glm::dvec2 camera(frame.camera.position.x, frame.camera.position.z);
  // Snapped to whole texels of the coarsest mip level the lookup filters with, so that every
  // level keeps its texels on the same world grid as the camera moves (a one-texel snap would
  // shift level k's texels by 2^-k of theirs and the filtered light would jump).
  const double snap = l.texel * double(1 << shared::IRRADIANCE_MIP_LEVELS);
  l.windowOrigin = glm::floor((camera - 0.5 * l.windowSize) / snap) * snap;
  const double gridSpan = l.windowSize * (1.0 + 2.0 * kGridMargin);
  l.cell = gridSpan / l.resolution;
  l.cells = l.resolution + 1;
  const glm::dvec3 down = refractedSunDown(glm::normalize(frame.sun.direction), frame.water.ior);
  // Flat-water drift per metre of depth; down.y <= -cos(critical angle) for any sun above the
  // horizon, so this is bounded (~1.1).
  const glm::dvec2 drift = glm::dvec2(down.x, down.z) / std::max(-down.y, 1e-6);
  const glm::dvec2 windowCentre = l.windowOrigin + 0.5 * l.windowSize;
  for (int k = 0; k < l.layers; ++k) {
    l.depth[k] = wavefrontAreaRatioLayerDepth(k, l.layers, s.maxReceiverDepth);
    const glm::dvec2 start = windowCentre - drift * l.depth[k] - 0.5 * gridSpan;
    l.gridOrigin[k] = glm::floor(start / l.cell) * l.cell;
  }
  l.spread = landingSpreadOn(frame);
  return l;
}

int wavefrontAreaRatioMipLevels(int resolution) {
  return std::min(glkit::mipLevelCount(resolution), shared::IRRADIANCE_MIP_LEVELS + 1);
}

std::uint64_t wavefrontAreaRatioBytes(int gridResolution, int depthLayers, bool spread) {
  std::uint64_t texels = 0;
  for (int level = 0; level < wavefrontAreaRatioMipLevels(gridResolution); ++level) {
    const std::uint64_t side = std::max(gridResolution >> level, 1);
    texels += side * side;
  }
  const std::uint64_t points =
      std::uint64_t(gridResolution + 2) * std::uint64_t(gridResolution + 2);
  return texels * std::uint64_t(depthLayers) * 4 + points * 2 * 16 +
         (spread ? layerSpreadBytes(gridResolution, depthLayers) : 0);
}

}  // namespace postfx::detail
