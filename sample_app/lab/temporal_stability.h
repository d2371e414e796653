#pragma once
// Temporal stability of one pass: how much the light it adds changes from one frame to the
// next, relative to how much light it adds. A pass that follows a slowly moving camera or
// slowly running time smoothly changes each frame a little; one that flickers (samples that
// slide with the camera, noise drawn anew each frame, popping levels of detail) changes more
// than the light it approximates does over the same step.
#include <vector>

#include <glm/glm.hpp>

namespace ocean {

// Over the pixels a pass lights in either frame of a pair of consecutive frames (dark in both:
// nothing to measure), and over every pair. L: Rec. 709 luminance of the added light.
struct AddedLightChange {
  // Mean of |L(k+1) - L(k)| over the mean of (L(k) + L(k+1)) / 2: 0 when nothing changes,
  // 0.01 for a 1 % change everywhere, 2 when the light jumps to where there was none.
  double mean = 0.0;
  // The 99th percentile of |L(k+1) - L(k)| over the same mean light: where the change is
  // largest (the mean hides a few pixels that pop).
  double p99 = 0.0;
  double meanLight = 0.0;  // the divisor, in the frame's own units
  int pairs = 0;           // consecutive frame pairs measured
};

// `frames`: the light a pass added to each frame of a sequence, RGBA (alpha ignored), all the
// same size, in order. Non-finite pixels are left out. Fewer than two frames, or frames that
// add no light, give all zeros.
AddedLightChange addedLightChange(const std::vector<std::vector<glm::vec4>>& frames);

}  // namespace ocean
