#pragma once
// Turns a FrameDesc into the god-ray passes' uniform block. The grid is snapped to the world
// here: the camera's coordinates in the rotated grid frame are computed in double and reduced
// modulo the plane spacing before they become float, so the planes stay where they are in the
// world (to float precision) however far the camera is from the origin.
#include <glm/glm.hpp>

#include <postfx/postfx.h>

#include "shared_math.h"

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
class GodRayGridPivot {
 public:
  // Moves the pivot to the grid lattice point nearest the camera (x', z' by whole spacings; y',
  // along which the planes run, freely): the same planes for this frame's grid. Returns it.
  const glm::dvec3& follow(const GodRayGrid& grid, double spacing, const glm::dvec3& camera);

 private:
  glm::dvec3 pivot_{0.0};
};

// Texels along a side of `size` pixels at `resolution` (a partial block gets a texel too): the
// march texture's size, which the pass allocates and the block describes.
inline int godRayReducedSize(int size, GodRayResolution resolution) {
  const int k = static_cast<int>(resolution);
  return (size + k - 1) / k;
}

// `width` x `height`: the target's. `pivot` is the context's: it follows the camera (see
// GodRayGridPivot).
shared::GodRaysBlock buildGodRaysBlock(const FrameDesc& frame, int width, int height,
                                       GodRayGridPivot& pivot);

}  // namespace postfx::detail
