#pragma once
// What happens in the pool preset, as a function of time only (deterministic: the same times give
// the same drops and the same ball on every machine): drops falling at fixed times onto places
// drawn from a hash of their number, and the ball's path through the water.
#include <glm/glm.hpp>

#include <vector>

namespace ocean {

struct ScriptedDrop {
  double time = 0.0;        // s
  glm::dvec2 centre{0.0};   // world x, z (m)
  double radius = 0.15;     // m
  double strength = -0.03;  // m, the height the drop adds at its centre (negative: a dent)
};

struct PoolScript {
  glm::dvec2 poolSize{8.0, 8.0};  // m, the water's rectangle, centred on the origin
  double sphereRadius = 0.6;      // m
  double dropInterval = 0.7;      // s between drops, > 0; drop k falls at k * dropInterval
};

// The drops that fall in (from, to] (s), in time order; none when to <= from. At most 10^5
// (a longer interval gives its last 10^5).
std::vector<ScriptedDrop> dropsBetween(const PoolScript& script, double from, double to);

// The ball's centre at `seconds` (world m, y above the level): a closed loop around the pool
// 1.2 m clear of the walls (periods 20 s along x, 13 s along z) while it bobs through the
// surface every 5 s (just under at the bottom, three-quarters out at the top); 1.5 m/s at most
// for the default pool. Repeats every 260 s.
glm::dvec3 sphereCentre(const PoolScript& script, double seconds);

}  // namespace ocean
