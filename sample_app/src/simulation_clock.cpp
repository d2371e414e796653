#include "simulation_clock.h"

#include <cmath>

namespace ocean {

bool SimulationClock::needsRestart(double seconds) const {
  const double now = timeAt(steps);
  // Half a step of slack: a frame at the simulation's own time is not "earlier".
  return !started_ || seconds < now - 0.5 / stepsPerSecond_ || seconds - now > maxCatchUp_;
}

void SimulationClock::restart(double seconds) {
  start_ = seconds - warmUp_;
  steps = 0;
  started_ = true;
}

long long SimulationClock::stepsAt(double seconds) const {
  return static_cast<long long>(std::floor((seconds - start_) * double(stepsPerSecond_) + 1e-6));
}

double SimulationClock::timeAt(long long step) const {
  return start_ + double(step) / double(stepsPerSecond_);
}

}  // namespace ocean
