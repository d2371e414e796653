#pragma once
// The seabed: one analytic height field, used both to build the render mesh and, exactly, by
// CPU references (photon tracing, placement of objects on the sand).
//
// Shape: base depth kSeabedBaseDepth, a gentle slope, three crossing dune trains (metres high,
// 17-47 m wavelength) and a field of sand ripples (3 cm high, 0.9 m wavelength) within
// kRippleFieldRadius of the origin, fading out by kRippleFadeRadius; and one sandbank far from
// the origin (the shallow preset's), whose top is 2.5-4.5 m deep. Ripples finer than this
// are left to the renderer's normal perturbation; the mesh could not carry them.

#include <glm/glm.hpp>

#include "scene/model.h"

namespace ocean_scene {

inline constexpr double kSeabedBaseDepth = -10.0;  // metres, water level is y = 0
// Everywhere: kSeabedMinHeight <= seabedHeight(x, z) <= kSeabedMaxHeight < 0 (the sum of the
// term amplitudes away from the sandbank, its top's measured maximum plus margin on it;
// checked by a test on a dense sample).
inline constexpr double kSeabedMaxHeight = -2.5;
inline constexpr double kSeabedMinHeight = -13.5;
inline constexpr double kRippleAmplitude = 0.03;    // metres
inline constexpr double kRippleWavelength = 0.9;    // metres
inline constexpr double kRippleFieldRadius = 20.0;  // full-strength ripples inside this radius
inline constexpr double kRippleFadeRadius = 35.0;   // no ripples beyond this radius

// The sandbank: a flat-topped mound raised kSandbankLift metres over the seabed around it,
// full height within kSandbankTopRadius of its centre, none beyond kSandbankFootRadius. It lies
// 64 m from the origin, more than the shadow map's 40 m from every deep preset's camera, so
// it changes nothing they see or light.
inline constexpr glm::dvec2 kSandbankXZ{-45.0, 45.0};
inline constexpr double kSandbankLift = 7.0;         // metres
inline constexpr double kSandbankTopRadius = 10.0;   // metres
inline constexpr double kSandbankFootRadius = 28.0;  // metres

// Height y of the seabed at world (x, z), metres.
double seabedHeight(double x, double z);
// (dh/dx, dh/dz), exact derivative of seabedHeight.
glm::dvec2 seabedGradient(double x, double z);
// Unit upward normal of the analytic surface.
glm::dvec3 seabedNormal(double x, double z);

struct SeabedMeshParams {
  double halfExtent = 150.0;  // the mesh covers [-halfExtent, halfExtent]^2 in x and z
  int resolution = 512;       // vertices per side (>= 2)
  // Vertex spacing at the centre, metres. The grid is graded: this fine near the origin, where
  // the ripples and the camera presets are, coarser towards the edges (about 2 m at the edge
  // for the defaults), which still resolves the dunes. Clamped so the grid is never coarser
  // than uniform at the centre.
  double centreSpacing = 0.2;
};

// Grid coordinate (x or z) of grid line `i` of `resolution`; exposed for tests and for hosts
// that want the exact sample positions.
double seabedGridCoordinate(int i, const SeabedMeshParams& params);

// Triangle mesh of the height field in world space with analytic normals; material 0.
Mesh buildSeabedMesh(const SeabedMeshParams& params);

}  // namespace ocean_scene
