#pragma once
// An animation as `render --frames N --fps F` writes it: the file name of each frame, the
// camera of each frame along the optional slow path, and how much each frame differs from the
// one before (the flicker measurement).
#include <string>
#include <vector>

#include "camera.h"
#include "options.h"

namespace ocean {

// "dir/ocean.png", frame 7 of 120 -> "dir/ocean_0007.png" (at least 4 digits, more when
// `frames` needs them so the names sort in order).
std::string sequenceFrameName(const std::string& path, int frame, int frames);

// The camera at `seconds` after the first frame: it moves at options.cameraVelocity (m/s) and,
// with --camera-look-at, keeps turning to the target. False when the path passes straight above
// or below the target or goes farther than 1e7 m from the origin.
bool cameraAt(const Options& options, const Camera& first, double seconds, Camera& camera);

// Mean |luminance(b) - luminance(a)| over the pixels, divided by the mean luminance of a (0 when
// a is black): 0 for identical frames, ~0.01 for a 1 % change everywhere. RGBA, linear.
double relativeFrameChange(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace ocean
