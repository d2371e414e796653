#include "reflected_caustics/reflected_layout.h"

#include <algorithm>
#include <cmath>

#include "core/shared_math.h"
#include "seabed_caustics/wavefront_area_ratio_layout.h"

namespace postfx::detail {

double reflectedLayerHeight(int k, int layers, double maxHeight) {
  const double f = static_cast<double>(k + 1) / static_cast<double>(std::max(layers, 1));
  return maxHeight * f * f;
}

ReflectedLayout reflectedLayout(const FrameDesc& frame) {
  const ReflectedCausticsSettings& s = frame.reflectedCaustics;
  ReflectedLayout l;
  l.resolution = s.gridResolution;
  l.layers = std::clamp(s.heightLayers, 1, kMaxReflectedLayers);
  l.windowSize = s.windowSize;
  l.texel = l.windowSize / l.resolution;
  const glm::dvec2 camera(frame.camera.position.x, frame.camera.position.z);
  // Snapped as the wavefront area ratio's window: every filtered level keeps its texels on one
  // world grid while the camera moves.
  const double snap = l.texel * double(1 << shared::IRRADIANCE_MIP_LEVELS);
  l.windowOrigin = glm::floor((camera - 0.5 * l.windowSize) / snap) * snap;
  // A mirror turns light by twice the slope: the grid reaches the margin beyond the window that
  // the refracted grid does (light mirrored from outside it lands in the fade band).
  const double gridSpan = l.windowSize * (1.0 + 2.0 * kGridMargin);
  l.cell = gridSpan / l.resolution;
  l.cells = l.resolution + 1;
  const glm::dvec3 sun = glm::normalize(frame.sun.direction);
  // sun.y > 0 (the pass runs only then), and validation bounds the direction's length.
  l.rise = -glm::dvec2(sun.x, sun.z) / sun.y;
  const glm::dvec2 windowCentre = l.windowOrigin + 0.5 * l.windowSize;
  for (int k = 0; k < l.layers; ++k) {
    l.height[k] = reflectedLayerHeight(k, l.layers, s.maxHeight);
    // The flat mirror ray from the grid's centre reaches the window's centre at this height.
    const glm::dvec2 start = windowCentre - l.rise * l.height[k] - 0.5 * gridSpan;
    l.gridOrigin[k] = glm::floor(start / l.cell) * l.cell;
  }
  return l;
}

std::uint64_t reflectedFieldBytes(int gridResolution, int layers) {
  return wavefrontAreaRatioBytes(gridResolution, layers, false);
}

}  // namespace postfx::detail
