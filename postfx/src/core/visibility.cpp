#include "core/visibility.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace postfx::detail {
namespace {

// Distance along the view axis (-Z) of window depth `ndcZ`, or +inf where the plane is at
// infinity (infinite reverse-Z projections).
double viewDistance(double ndcZ, const glm::dmat4& projection) {
  const double p22 = projection[2][2], p32 = projection[3][2];
  const double viewZ = -p32 / (ndcZ + p22);
  if (!std::isfinite(viewZ) || viewZ >= 0.0) return std::numeric_limits<double>::infinity();
  return -viewZ;
}

}  // namespace

namespace {

// The lowest and highest heights (relative to the camera) the frustum's corner edges reach
// between the near and far planes; infinite along an edge that climbs or falls to an infinite
// far plane. False for a projection it does not understand.
bool frustumHeights(const glm::dmat3& viewToWorld, const glm::dmat4& projection,
                    DepthConvention depthConvention, double& lowest, double& highest) {
  // NDC depth of the near and far planes per convention (0 reverse-Z, 1 fwd [0,1], 2 fwd [-1,1]).
  const bool reverse = depthConvention == DepthConvention::ReverseZ;
  const double nearNdc =
      reverse ? 1.0 : (depthConvention == DepthConvention::ForwardZeroToOne ? 0.0 : -1.0);
  const double farNdc = reverse ? 0.0 : 1.0;
  const double nearDistance = viewDistance(nearNdc, projection);
  const double farDistance = viewDistance(farNdc, projection);
  if (!std::isfinite(nearDistance)) return false;
  lowest = std::numeric_limits<double>::infinity();
  highest = -lowest;
  for (int corner = 0; corner < 4; ++corner) {
    const double ndcX = (corner & 1) ? 1.0 : -1.0;
    const double ndcY = (corner & 2) ? 1.0 : -1.0;
    // Direction of the corner edge, scaled to 1 m along the view axis.
    const glm::dvec3 view((ndcX + projection[2][0]) / projection[0][0],
                          (ndcY + projection[2][1]) / projection[1][1], -1.0);
    const double dy = (viewToWorld * view).y;
    lowest = std::min(lowest, dy * nearDistance);
    highest = std::max(highest, dy * nearDistance);
    if (dy < 0.0) lowest = std::min(lowest, dy * farDistance);  // -inf for an infinite far plane
    if (dy > 0.0) highest = std::max(highest, dy * farDistance);
  }
  return true;
}

}  // namespace

bool frustumReachesBelowWater(const glm::dmat3& viewToWorld, const glm::dmat4& projection,
                              DepthConvention depthConvention, double levelRelative) {
  if (levelRelative >= 0.0) return true;  // the camera itself is at or under the level
  double lowest = 0.0, highest = 0.0;
  if (!frustumHeights(viewToWorld, projection, depthConvention, lowest, highest))
    return true;  // not a projection we understand: run
  return lowest < levelRelative;
}

bool frustumReachesAboveWater(const glm::dmat3& viewToWorld, const glm::dmat4& projection,
                              DepthConvention depthConvention, double levelRelative) {
  if (levelRelative <= 0.0) return true;  // the camera itself is at or above the level
  double lowest = 0.0, highest = 0.0;
  if (!frustumHeights(viewToWorld, projection, depthConvention, lowest, highest)) return true;
  return highest > levelRelative;
}

}  // namespace postfx::detail
