#pragma once
// What every extreme case asserts, and the bounds derived from the model (not measured):
//   * finiteness of every output value,
//   * the model's physical bounds (extreme_runner.cpp fills Output::bound),
//   * continuity: a step h = 1e-4 of the swept parameter changes the output by at most the
//     derived Lipschitz bound, measured as the mean absolute change over the image relative to
//     the output's full scale.
#include <string>

#include "extreme_case.h"
#include "extreme_runner.h"

namespace extreme {

// Number of NaN/Inf values among the outputs (light rgb, raw factor, water texels).
size_t nonFiniteCount(const Output& out);

// Largest violation of the model's bounds, as a fraction of the full scale (<= 0: none), and
// where and what it was.
struct Excess {
  double worst = 0.0;
  std::string where;
};
Excess boundExcess(const Output& out, Pass pass);

// Whether a row's sweep is checked on the world grid (grid-invariant parameters) or with the
// grid factored out (UniformAlongRay) for the god-ray passes; see extreme_bounds.cpp.
bool continuityNeedsUniformSampling(Pass pass, Sweep sweep);

struct Continuity {
  double change = 0.0;  // mean |output(p + h) - output(p)| / full scale
  double limit = 0.0;   // derived bound of the same quantity
  std::string derivation;
};
Continuity continuity(Pass pass, Sweep sweep, const Knobs& knobs, const Output& base,
                      const Output& moved);

}  // namespace extreme
