#pragma once
// Deterministic wild values for the dispatch fuzz: IEEE specials, values at and past every
// documented bound, far magnitudes, and perturbations of the valid base value. Every conversion
// to a narrower type saturates (a double past FLT_MAX becomes +-Inf, never undefined behaviour),
// so the fuzz itself stays clean under UBSan.
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace postfxfuzz {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, n).
  int below(int n) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(n)); }
  double uniform(double lo, double hi) {
    return lo + (hi - lo) * (static_cast<double>(engine_() >> 11) * 0x1.0p-53);
  }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
  std::uint64_t bits() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

inline float toFloat(double d) {
  if (std::isnan(d)) return std::numeric_limits<float>::quiet_NaN();
  if (d > double(FLT_MAX)) return std::numeric_limits<float>::infinity();
  if (d < -double(FLT_MAX)) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(d);
}

inline double wild(Rng& r, double base) {
  static const double specials[] = {std::numeric_limits<double>::quiet_NaN(),
                                    std::numeric_limits<double>::infinity(),
                                    -std::numeric_limits<double>::infinity(),
                                    0.0,
                                    -0.0,
                                    4.9e-324,
                                    1e-300,
                                    -1e-300,
                                    1e-45,
                                    1e-6,
                                    -1e-6,
                                    1.0,
                                    -1.0,
                                    1e6,
                                    -1e6,
                                    1e9,
                                    -1e9,
                                    1.0000001e9,
                                    1e15,
                                    -1e15,
                                    1e30,
                                    3.5e38,
                                    1e300,
                                    -1e300,
                                    DBL_MAX,
                                    -DBL_MAX};
  switch (r.below(4)) {
    case 0:
      return specials[r.below(static_cast<int>(std::size(specials)))];
    case 1:
      return base * r.uniform(-2.0, 3.0);
    case 2:
      return base + r.uniform(-1.0, 1.0) * std::pow(10.0, r.uniform(-6.0, 12.0));
    default:
      return r.uniform(-1.0, 1.0) * std::pow(10.0, r.uniform(-40.0, 40.0));
  }
}

inline float wildFloat(Rng& r, float base) {
  return toFloat(wild(r, base));
}

inline std::int64_t wildInt64(Rng& r, std::int64_t base) {
  static const std::int64_t specials[] = {
      std::numeric_limits<std::int64_t>::min(),
      -1,
      0,
      1,
      2,
      3,
      4,
      7,
      8,
      9,
      15,
      16,
      17,
      64,
      65,
      1024,
      2048,
      2049,
      16384,
      1 << 20,
      std::numeric_limits<std::int32_t>::max(),
      std::int64_t(std::numeric_limits<std::int32_t>::max()) + 1,
      384307168202282566,
      std::numeric_limits<std::int64_t>::max() - 100,
      std::numeric_limits<std::int64_t>::max()};
  switch (r.below(3)) {
    case 0:
      return specials[r.below(static_cast<int>(std::size(specials)))];
    case 1:
      return base + r.below(9) - 4;
    default:
      return base * (r.below(5) - 1) + r.below(3);
  }
}

inline int wildInt(Rng& r, int base) {
  const std::int64_t v = wildInt64(r, base);
  if (v > std::numeric_limits<int>::max()) return std::numeric_limits<int>::max();
  if (v < std::numeric_limits<int>::min()) return std::numeric_limits<int>::min();
  return static_cast<int>(v);
}

}  // namespace postfxfuzz
