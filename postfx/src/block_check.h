#pragma once
// Every uniform block is all floats (vec4/mat4, see shaders/shared/*_block.h) filled from
// doubles. A double that is finite can still overflow float, and a subtraction of two far
// positions can overflow double: this is the last check that nothing reaches the GPU as Inf or
// NaN, run on each block before any GL work, so that a frame it fails is refused untouched.
#include <cmath>
#include <cstring>

namespace postfx::detail {

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
