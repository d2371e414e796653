#include "reflected_caustics/reflected_layout.h"

#include <algorithm>
#include <cmath>

#include "core/frame_geometry.h"
#include "core/shared_math.h"
#include "seabed_caustics/layer_spread.h"
#include "seabed_caustics/tile_irradiance_pass.h"
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
  // Centred ahead of the camera, where what it sees lies: the receivers of reflected light
  // face the water and stand across it (a wall, a hull, a pier), mostly farther than the water
  // the view also shows. A quarter of the window stays behind the camera for what the view's
  // sides reach; looking straight down or up it centres on the camera.
  const glm::dvec3 forward = viewToWorldRotation(frame.camera.view) * glm::dvec3(0.0, 0.0, -1.0);
  const glm::dvec2 ahead =
      glm::dvec2(forward.x, forward.z) * (kReflectedWindowAhead * double(s.windowSize));
  const glm::dvec2 centre =
      glm::dvec2(frame.camera.position.x, frame.camera.position.z) +
      (std::isfinite(ahead.x) && std::isfinite(ahead.y) ? ahead : glm::dvec2(0.0));
  // Snapped as the wavefront area ratio's window: every filtered level keeps its texels on one
  // world grid while the camera moves.
  const double snap = l.texel * double(1 << shared::IRRADIANCE_MIP_LEVELS);
  l.windowOrigin = glm::floor((centre - 0.5 * l.windowSize) / snap) * snap;
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
  l.spread = landingSpreadOn(frame);
  return l;
}

std::uint64_t reflectedFieldBytes(int gridResolution, int layers, bool spread) {
  // The refracted window's layers and grid points, with every channel's layers; the spread blurs
  // one channel's layers at a time.
  return wavefrontAreaRatioBytes(gridResolution, kReflectedChannels * layers, false) +
         (spread ? layerSpreadBytes(gridResolution, layers) : 0);
}

namespace {

// Horizontal offset per metre of height of sunlight from `towardSun` mirrored by a surface of
// unit normal `normal`.
glm::dvec2 mirroredOffsetPerHeight(const glm::dvec3& towardSun, const glm::dvec3& normal) {
  const glm::dvec3 r = glm::reflect(-towardSun, normal);
  return glm::dvec2(r.x, r.z) / std::max(r.y, 1e-6);
}

}  // namespace

std::uint64_t reflectedReceiverBytes(int gridResolution, int targetWidth, int targetHeight,
                                     bool slopeSpread) {
  const std::uint64_t side = std::uint64_t(gridResolution) + 1;
  return side * side * 2 * 16 + std::uint64_t(targetWidth) * std::uint64_t(targetHeight) * 16 +
         (slopeSpread ? tileSpreadStatisticsBytes() : 0);
}

glm::dvec4 reflectedLandingJacobian(const glm::dvec3& towardSun) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  auto offset = [&](double sx, double sz) {
    return mirroredOffsetPerHeight(sun, glm::normalize(glm::dvec3(-sx, 1.0, -sz)));
  };
  const double e = 1e-5;
  const glm::dvec2 dx = (offset(e, 0.0) - offset(-e, 0.0)) / (2.0 * e);
  const glm::dvec2 dz = (offset(0.0, e) - offset(0.0, -e)) / (2.0 * e);
  return glm::dvec4(dx, dz);
}

glm::dvec3 reflectedSunDiscCovariance(const glm::dvec3& towardSun, double angularRadius) {
  const glm::dvec3 sun = glm::normalize(towardSun);
  const glm::dvec3 helper =
      std::abs(sun.y) < 0.9 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(1.0, 0.0, 0.0);
  const glm::dvec3 side = glm::normalize(glm::cross(sun, helper));
  const glm::dvec3 up = glm::cross(side, sun);
  const glm::dvec3 flat(0.0, 1.0, 0.0);
  auto offset = [&](const glm::dvec3& toward) {
    return mirroredOffsetPerHeight(glm::normalize(toward), flat);
  };
  const double e = 1e-5;
  const glm::dvec2 a = (offset(sun + e * side) - offset(sun - e * side)) / (2.0 * e);
  const glm::dvec2 b = (offset(sun + e * up) - offset(sun - e * up)) / (2.0 * e);
  // A uniform disc of radius r has variance r^2 / 4 along each of its axes.
  const double v = 0.25 * angularRadius * angularRadius;
  return v * glm::dvec3(a.x * a.x + b.x * b.x, a.x * a.y + b.x * b.y, a.y * a.y + b.y * b.y);
}

}  // namespace postfx::detail
