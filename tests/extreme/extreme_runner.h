#pragma once
// Turns a row's knobs into host inputs (G-buffer, water texture, shadow map, frame), runs one
// pass and reads back every output, with the facts about the scene the bounds are derived from.
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "extreme_case.h"

namespace extreme {

// What the bounds need to know about the inputs (all derived, none measured from the output).
struct Facts {
  double cosRefracted = 1.0;  // cos(theta_t): refracted sun's angle from the vertical
  double tanRefracted = 0.0;
  double maxDepth = 0.0;       // deepest receiver or god-ray sample below the level (m)
  double maxMarch = 0.0;       // longest god-ray march (m)
  double slopeGradient = 0.0;  // sup |grad of the summed water slopes| (1/m)
  double slopeRate = 0.0;      // sup |d(summed slopes)/dt| (1/s), the water module's texture
  int width = 0, height = 0;
  std::vector<float> rayUp;        // per pixel: the y component of the unit world view ray
  std::vector<float> hitDistance;  // per pixel: distance to the surface seen (maxMarch: sky)
};

struct Output {
  std::string error;             // non-empty: the pass refused the inputs
  std::string note;              // what a broken input texel holds after upload (printed)
  std::vector<glm::vec4> light;  // plugin: light added into a zero target; water: all texels
  std::vector<float> raw;        // caustic passes: the raw caustic factor
  glm::vec3 bound{0.0f};         // the model's upper bound of `light` per channel (>= 0)
  glm::vec3 fullScale{1.0f};     // the output range the continuity change is relative to
  Facts facts;
  // Water pass: per-texel sup bounds of |rgb| (slopes, height) and |a| (Jacobian) of its cascade
  // and the sup |d slope/dt| of its cascade.
  std::vector<glm::vec4> texelBound;
  std::vector<float> texelRate;
};

class Runner {
 public:
  explicit Runner(Pass pass);
  ~Runner();
  Runner(const Runner&) = delete;
  Runner& operator=(const Runner&) = delete;
  Output run(const Knobs& knobs);

 private:
  struct State;
  Pass pass_;
  std::unique_ptr<State> state_;
};

}  // namespace extreme
