#include "pool_script.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace ocean {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr std::int64_t kMaxDrops = 100000;

// splitmix64: a deterministic stream of 64-bit values from the drop's number.
std::uint64_t mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

// Uniform in [0, 1) from the top 53 bits.
double unit(std::uint64_t bits) {
  return double(bits >> 11) * (1.0 / 9007199254740992.0);
}

ScriptedDrop dropNumber(const PoolScript& script, std::int64_t k) {
  const std::uint64_t seed = mix(std::uint64_t(k));
  ScriptedDrop drop;
  drop.time = double(k) * script.dropInterval;
  // Anywhere at least half a metre inside the walls.
  const glm::dvec2 inside = glm::max(script.poolSize * 0.5 - 0.5, glm::dvec2(0.0));
  drop.centre = glm::dvec2((2.0 * unit(mix(seed ^ 1)) - 1.0) * inside.x,
                           (2.0 * unit(mix(seed ^ 2)) - 1.0) * inside.y);
  drop.radius = 0.10 + 0.12 * unit(mix(seed ^ 3));
  // Mostly the dent an impact makes, one in four a splash-back bump: the mean level barely moves.
  const double size = 0.015 + 0.025 * unit(mix(seed ^ 4));
  drop.strength = (mix(seed ^ 5) % 4 == 0) ? size : -size;
  return drop;
}

}  // namespace

std::vector<ScriptedDrop> dropsBetween(const PoolScript& script, double from, double to) {
  std::vector<ScriptedDrop> drops;
  if (!(to > from) || !(script.dropInterval > 0.0) || !std::isfinite(from) || !std::isfinite(to))
    return drops;
  // Drop k falls at k * interval: the first after `from` and the last at or before `to`.
  const double first = std::floor(from / script.dropInterval) + 1.0;
  const double last = std::floor(to / script.dropInterval);
  if (!(last >= first)) return drops;
  const double start = std::max(first, last - double(kMaxDrops - 1));
  for (double k = start; k <= last; k += 1.0) drops.push_back(dropNumber(script, std::int64_t(k)));
  return drops;
}

glm::dvec3 sphereCentre(const PoolScript& script, double seconds) {
  // Wrapped at the loop's whole period (260 s = lcm of 20, 13 and 5), in double, so a late
  // time keeps its precision.
  const double t = std::fmod(seconds, 260.0);
  const glm::dvec2 reach =
      glm::max(script.poolSize * 0.5 - script.sphereRadius - 1.2, glm::dvec2(0.0));
  const double r = script.sphereRadius;
  return {reach.x * std::sin(kTwoPi * t / 20.0),
          // From 1.2 r under (its top 0.2 r below the level) to 0.5 r above (a quarter in).
          -0.35 * r + 0.85 * r * std::sin(kTwoPi * t / 5.0),
          reach.y * std::sin(kTwoPi * t / 13.0 + 0.5)};
}

}  // namespace ocean
