#pragma once
// Where the interesting things of the default scene are, so camera presets and tests can aim at
// them. World space: metres, y up, water at y = 0, seabed near y = -10 (see seabed.h).
// Positions are (x, z) on the seabed unless stated; heights follow the sand via seabedHeight.

#include <glm/glm.hpp>

namespace ocean_scene::features {

// Square stone pillar, 2 m x 2 m, rotated kPillarYawDeg about y, from below the sand up to
// kPillarTopY: vertical faces for tri-planar projection, a top face in full light.
inline constexpr glm::dvec2 kPillarXZ{6.0, -3.0};
inline constexpr double kPillarHalfWidth = 1.0;
inline constexpr double kPillarTopY = -2.0;
inline constexpr double kPillarYawDeg = 20.0;

// Round column (a ruin), radius 0.6 m, top at kColumnTopY: smooth horizontal normals.
inline constexpr glm::dvec2 kColumnXZ{-4.0, -7.0};
inline constexpr double kColumnRadius = 0.6;
inline constexpr double kColumnTopY = -5.0;

// Axis-aligned wall, 0.8 m thick (x) and 10 m long (z), top at kWallTopY; its -x face looks
// back at the origin.
inline constexpr glm::dvec2 kWallXZ{14.0, 4.0};
inline constexpr glm::dvec3 kWallHalfExtent{0.4, 0.0, 5.0};  // y is set by the sand and top
inline constexpr double kWallTopY = -4.5;

// Rock arch: a noisy elliptical tube bent over a half circle in the plane z = kArchXZ.y, feet
// at x = kArchXZ.x +- kArchRadius, buried in the sand. The centreline apex is about
// kArchRadius above the sand; its underside (normals pointing down) is in the arch's own
// shadow for a high sun: the overhang case for caustics and shadow masking.
inline constexpr glm::dvec2 kArchXZ{-9.0, 6.0};
inline constexpr double kArchRadius = 6.0;             // centreline radius
inline constexpr double kArchHalfThickness = 0.9;      // in the arch plane
inline constexpr double kArchHalfDepth = 1.5;          // along z, across the arch
inline constexpr glm::dvec2 kArchShadowXZ{-9.0, 6.0};  // sand right under the apex

// glTF models placed by defaultModelPlacements() (see default_scene.h).
// Glass sphere (radius 0.5 m) suspended kGlassSphereHeightAboveSand above the sand: for
// water -> glass (relative IOR 1.5 / 1.33) its paraxial focus is about 2.2 m from the centre,
// so the focused caustic lands near the sand below it.
inline constexpr glm::dvec2 kGlassSphereXZ{1.0, 7.0};
inline constexpr double kGlassSphereHeightAboveSand = 1.0;  // centre above sand
inline constexpr glm::dvec2 kMetalRingXZ{2.7, 8.6};         // lying flat on the sand
inline constexpr glm::dvec2 kGlassBottleXZ{-0.8, 8.4};      // standing on the sand
inline constexpr glm::dvec2 kAmphoraXZ{-5.0, 2.5};          // on its side, half buried

// The shallow preset's reef on the sandbank (seabed.h's kSandbankXZ, sand 2.5-4.5 m deep): a
// second glass sphere, held kShallowSphereHeightAboveSand above the sand so that its 2.2 m
// focus falls just under the sand (the tightest spot a high sun gives), a brass ring beside it
// for the reflected cardioid, and reef rocks around them. Far from the origin so the deep
// presets' casters and shadow maps never include them.
inline constexpr glm::dvec2 kShallowSphereXZ{-45.6, 45.4};
inline constexpr double kShallowSphereHeightAboveSand = 1.9;
inline constexpr glm::dvec2 kShallowRingXZ{-44.0, 45.9};
struct ReefRock {
  double x, z, radius;
};
inline constexpr ReefRock kReefRocks[] = {{-48.0, 43.2, 1.1},  {-42.4, 43.8, 0.8},
                                          {-47.6, 47.4, 0.55}, {-43.0, 41.5, 1.5},
                                          {-49.5, 40.5, 1.8},  {-41.0, 46.8, 0.5}};

}  // namespace ocean_scene::features
