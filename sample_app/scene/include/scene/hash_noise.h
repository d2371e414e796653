#pragma once
// Deterministic hashing and noise. The scene must be bit-identical on every platform and
// standard library, which std:: distributions do not promise, so everything here is integer
// hashing plus plain arithmetic.

#include <cstdint>

#include <glm/glm.hpp>

namespace ocean_scene {

// A well-mixed 32-bit hash (lowbias32 by Chris Wellons).
std::uint32_t hash32(std::uint32_t x);
std::uint32_t hashCombine(std::uint32_t seed, std::uint32_t value);

// Sequential generator: the n-th draw depends only on the seed and n.
class HashRng {
 public:
  explicit HashRng(std::uint32_t seed) : state_(hash32(seed)) {}
  std::uint32_t nextU32();
  double uniform();                      // [0, 1)
  double uniform(double lo, double hi);  // [lo, hi)

 private:
  std::uint32_t state_;
  std::uint32_t counter_ = 0;
};

// Smoothly interpolated lattice value noise in [-1, 1], C1 continuous.
double valueNoise3(const glm::dvec3& p, std::uint32_t seed);
// Sum of `octaves` value-noise octaves, each twice the frequency and half the amplitude.
// The result stays within [-1, 1].
double fbm3(const glm::dvec3& p, int octaves, std::uint32_t seed);

}  // namespace ocean_scene
