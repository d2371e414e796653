#pragma once
// A deterministic Gaussian source: splitmix64 and Box-Muller, so the sea is the same bit for bit
// on every run (std::normal_distribution is implementation-defined).
#include <cmath>
#include <cstdint>
#include <numbers>

namespace postfx::water {

class GaussianRandom {
 public:
  explicit GaussianRandom(uint64_t seed) : state_(seed) {}

  uint64_t nextBits() {
    uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }

  // Uniform in (0, 1]: never 0, so log() below is finite.
  double nextUniform() { return static_cast<double>((nextBits() >> 11) + 1) * 0x1.0p-53; }

  // Two independent standard normal variates.
  void nextPair(double& first, double& second) {
    const double radius = std::sqrt(-2.0 * std::log(nextUniform()));
    const double angle = 2.0 * std::numbers::pi * nextUniform();
    first = radius * std::cos(angle);
    second = radius * std::sin(angle);
  }

 private:
  uint64_t state_;
};

}  // namespace postfx::water
