#include "scene/hash_noise.h"

#include <cmath>

namespace ocean_scene {

std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

std::uint32_t hashCombine(std::uint32_t seed, std::uint32_t value) {
  return hash32(seed ^ (value + 0x9e3779b9U + (seed << 6) + (seed >> 2)));
}

std::uint32_t HashRng::nextU32() {
  return hashCombine(state_, counter_++);
}

double HashRng::uniform() {
  // 24 bits keep the value exactly representable and strictly below 1.
  return static_cast<double>(nextU32() >> 8) * (1.0 / 16777216.0);
}

double HashRng::uniform(double lo, double hi) {
  return lo + (hi - lo) * uniform();
}

namespace {

double latticeValue(std::int64_t x, std::int64_t y, std::int64_t z, std::uint32_t seed) {
  std::uint32_t h = hashCombine(seed, static_cast<std::uint32_t>(x));
  h = hashCombine(h, static_cast<std::uint32_t>(y));
  h = hashCombine(h, static_cast<std::uint32_t>(z));
  return static_cast<double>(h >> 8) * (2.0 / 16777215.0) - 1.0;
}

double smootherStep(double t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

double lerp(double a, double b, double t) {
  return a + (b - a) * t;
}

}  // namespace

double valueNoise3(const glm::dvec3& p, std::uint32_t seed) {
  const glm::dvec3 cell = glm::floor(p);
  const glm::dvec3 f = p - cell;
  const auto x0 = static_cast<std::int64_t>(cell.x);
  const auto y0 = static_cast<std::int64_t>(cell.y);
  const auto z0 = static_cast<std::int64_t>(cell.z);
  const double u = smootherStep(f.x), v = smootherStep(f.y), w = smootherStep(f.z);
  double plane[2];
  for (int dz = 0; dz < 2; ++dz) {
    const double a =
        lerp(latticeValue(x0, y0, z0 + dz, seed), latticeValue(x0 + 1, y0, z0 + dz, seed), u);
    const double b = lerp(latticeValue(x0, y0 + 1, z0 + dz, seed),
                          latticeValue(x0 + 1, y0 + 1, z0 + dz, seed), u);
    plane[dz] = lerp(a, b, v);
  }
  return lerp(plane[0], plane[1], w);
}

double fbm3(const glm::dvec3& p, int octaves, std::uint32_t seed) {
  double sum = 0.0, amplitude = 1.0, norm = 0.0;
  glm::dvec3 q = p;
  for (int i = 0; i < octaves; ++i) {
    sum += amplitude * valueNoise3(q, seed + static_cast<std::uint32_t>(i) * 101U);
    norm += amplitude;
    amplitude *= 0.5;
    q *= 2.0;
  }
  return norm > 0.0 ? sum / norm : 0.0;
}

}  // namespace ocean_scene
