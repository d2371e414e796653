// The flux the clamp removes, counted in fixed point (1/256 of a texel of flat-water flux) as
// a 64-bit sum in two words, so the host can read the bias the clamp introduces.
#include "postfx/common/postfx_bindings.h"

layout(std430, binding = POSTFX_STORAGE_CLAMP_COUNT) buffer ClampCount {
  uint removedLow;
  uint removedHigh;
};

void countRemoved(float flux) {
  if (!(flux > 0.0)) return;
  uint units = uint(min(flux * 256.0 + 0.5, 4.0e9));
  uint before = atomicAdd(removedLow, units);
  if (before + units < before) atomicAdd(removedHigh, 1u);  // carry
}
