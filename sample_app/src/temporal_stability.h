#pragma once
// Temporal stability of one pass: how much the light it adds changes from one frame to the
// next, relative to how much light it adds. A pass that follows a slowly moving camera or
// slowly running time smoothly changes each frame a little; one that flickers (samples that
// slide with the camera, noise drawn anew each frame, popping levels of detail) changes more
// than the light it approximates does over the same step.
#include <vector>

#include <glm/glm.hpp>

namespace ocean {

struct AddedLightChange {
  // Over every pixel and every pair of consecutive frames, of |L(k+1) - L(k)| (Rec. 709
  // luminance of the added light), divided by the mean added luminance over the pixels and
  // frames: 0 when nothing changes, 0.01 for a 1 % change everywhere.
  double mean = 0.0;
  double p99 = 0.0;        // the 99th percentile instead of the mean (where the change is)
  double meanLight = 0.0;  // the divisor: mean added luminance (the frame's own units)
  int pairs = 0;           // consecutive frame pairs measured
};

// `frames`: the light a pass added to each frame of a sequence, RGBA (alpha ignored), all the
// same size, in order. Non-finite pixels are left out of both numbers. Fewer than two frames,
// or frames that add no light, give all zeros.
AddedLightChange addedLightChange(const std::vector<std::vector<glm::vec4>>& frames);

}  // namespace ocean
