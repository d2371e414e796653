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

// `reducedWidth` x `reducedHeight`: the size of the march texture (the target's at full res).
shared::GodRaysBlock buildGodRaysBlock(const FrameDesc& frame, int reducedWidth, int reducedHeight);

}  // namespace postfx::detail
