#pragma once
// Every uniform block is all floats (vec4/mat4, see shaders/shared/*_block.h) filled from
// doubles. A double that is finite can still overflow float, and a subtraction of two far
// positions can overflow double: this is the last check that nothing reaches the GPU as Inf or
// NaN, run on each block before any GL work, so that a frame it fails is refused untouched.
#include <cfloat>
#include <cmath>
#include <cstring>

#include <glm/glm.hpp>

namespace postfx::detail {

// double -> float where the value may exceed float's range (a host matrix of any finite
// magnitude times a position): +-Inf past FLT_MAX, never the undefined behaviour of a plain
// cast (UBSan's float-cast-overflow), so that allFinite() below refuses it.
inline float saturatedFloat(double value) {
  if (value > double(FLT_MAX)) return HUGE_VALF;
  if (value < -double(FLT_MAX)) return -HUGE_VALF;
  return static_cast<float>(value);  // NaN stays NaN
}
template <int C, int R>
glm::mat<C, R, float> saturatedFloat(const glm::mat<C, R, double>& m) {
  glm::mat<C, R, float> out;
  for (int c = 0; c < C; ++c)
    for (int r = 0; r < R; ++r) out[c][r] = saturatedFloat(m[c][r]);
  return out;
}

template <typename Block>
bool allFinite(const Block& block) {
  static_assert(sizeof(Block) % sizeof(float) == 0, "a block of floats");
  float values[sizeof(Block) / sizeof(float)];
  std::memcpy(values, &block, sizeof(Block));
  for (float v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace postfx::detail
