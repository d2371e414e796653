#pragma once
// Builders for the individual pieces of the default scene. Each returns a mesh in its own
// local space; the default scene places them. Exposed so tests and tools can check them alone.

#include <cstdint>

#include <glm/glm.hpp>

#include "scene/model.h"

namespace ocean_scene {

struct RockParams {
  double radius = 1.0;                // mean radius, metres
  glm::dvec3 stretch{1.0, 0.7, 1.1};  // per-axis scale applied after displacement
  double roughness = 0.4;             // displacement amplitude as a fraction of radius
  int subdivisions = 3;               // icosphere level: 3 = 642 vertices
  std::uint32_t seed = 1;
};

// A lumpy rock centred at the origin (noise-displaced icosphere, smooth normals).
Mesh buildRock(const RockParams& params, const std::string& name);

// Rock arch around local origin: centreline is the half circle of radius
// features::kArchRadius in the xy plane, extended below y = 0 at both feet by `footDepth`
// metres so the feet can be buried. Normals are smooth.
Mesh buildArch(double footDepth, std::uint32_t seed);

// Lowest sand height under a square footprint (sampled densely), used to bury bases.
double lowestSandUnder(const glm::dvec2& centre, double halfSize);

}  // namespace ocean_scene
