#pragma once
// Turns a FrameDesc into the god-ray passes' uniform block. The grid is snapped to the world
// here: the camera's coordinates in the rotated grid frame are computed in double and reduced
// modulo the plane spacing before they become float, so the planes stay where they are in the
// world (to float precision) however far the camera is from the origin.
#include <glm/glm.hpp>

#include <postfx/postfx.h>
#include <postfx/testing.h>

#include "core/shared_math.h"

namespace postfx::detail {

// Orthonormal grid frame: y = the refracted sun reversed (toward the sun, under water), x = the
// horizontal normal of the plane of incidence, z = x cross y.
struct GodRayGrid {
  glm::dvec3 x{1.0, 0.0, 0.0}, y{0.0, 1.0, 0.0}, z{0.0, 0.0, 1.0};
};
GodRayGrid godRayGrid(const glm::dvec3& towardSun, double ior);

// value - floor(value / spacing) * spacing, in [0, spacing).
double godRayGridPhase(double value, double spacing);

// The point the grid's planes pass through, kept next to the camera without moving a plane.
// When the sun turns, the grid turns about this point: were it the world origin, a camera 1e6 m
// away would see every plane sweep 1e6 * (the sun's turn) metres, so a slowly setting sun would
// reshuffle all samples every frame (flicker). Kept next to the camera, nearby planes move by
// about spacing * (the turn) instead, as they do near the origin. A context's state: starts at
// the world origin.
//
// The state is an anchor the current lattice passes through, not a running sum: while the grid
// holds still the pivot is recomputed from the anchor each frame, so no camera position (1e9 m
// out, say) leaves rounding behind. The anchor leaves the world origin only when the grid turns
// by less than kMaxContinuousTurn with the camera more than kOriginReach spacings from the
// origin (nearer, turning about the origin moves the nearby planes by at most kOriginReach *
// spacing * turn, 1 % of a spacing per 1e-4 rad); it then moves to the last pivot. A larger turn
// or another spacing is a cut, and a cut anchors the lattice at the origin again, exactly as in
// a fresh context. So only a sun turning slowly while the camera is far keeps a history.
class GodRayGridPivot {
 public:
  static constexpr double kMaxContinuousTurn = 0.01;  // radians per frame (0.57 degrees)
  static constexpr double kSameGrid = 1e-12;          // radians: below it the grid holds still
  static constexpr double kOriginReach = 128.0;       // spacings

  // The grid lattice point nearest the camera (x', z' by whole spacings from the anchor; y',
  // along which the planes run, freely): the same planes for this frame's grid. Returns it.
  const glm::dvec3& follow(const GodRayGrid& grid, double spacing, const glm::dvec3& camera);

 private:
  glm::dvec3 anchor_{0.0}, pivot_{0.0};
  GodRayGrid grid_;
  double spacing_ = 0.0;  // 0: no frame yet
};

// Texels along a side of `size` pixels at `resolution` (a partial block gets a texel too): the
// march texture's size, which the pass allocates and the block describes.
inline int godRayReducedSize(int size, GodRayResolution resolution) {
  const int k = static_cast<int>(resolution);
  return (size + k - 1) / k;
}

// `width` x `height`: the target's. `pivot` follows the camera (see GodRayGridPivot); pass a
// copy of the context's and keep it only once the frame is drawn. `uniformSampling`: the test
// hook testing::GodRaySampling::UniformAlongRay instead of the world grid, its samples at
// `uniformPhase` of each step (testing::setGodRayUniformPhase).
shared::GodRaysBlock buildGodRaysBlock(const FrameDesc& frame, int width, int height,
                                       GodRayGridPivot& pivot, bool uniformSampling = false,
                                       float uniformPhase = 0.5f);

}  // namespace postfx::detail
