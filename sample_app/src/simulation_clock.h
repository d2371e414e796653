#pragma once
// The frame clock of a simulation that runs in whole steps (the pool's ripples, a wake): it
// starts at rest `warmUp` seconds before the first frame's time, so that frame already shows
// water in motion, and each later frame runs the steps up to its time. A frame earlier than the
// simulation (the view jumped back) or more than `maxCatchUp` later starts it again the same
// way. Whole steps only: frames at the same times give the same water on every machine.
namespace ocean {

class SimulationClock {
 public:
  SimulationClock(int stepsPerSecond, double warmUpSeconds, double maxCatchUpSeconds)
      : stepsPerSecond_(stepsPerSecond), warmUp_(warmUpSeconds), maxCatchUp_(maxCatchUpSeconds) {}

  // True when `seconds` (finite) needs restart() first.
  bool needsRestart(double seconds) const;
  // The simulation is at rest at seconds - warmUp, after 0 steps.
  void restart(double seconds);
  // The steps done by `seconds`: whole steps from the rest.
  long long stepsAt(double seconds) const;
  // The clock's time after `step` steps (s).
  double timeAt(long long step) const;
  // Steps run so far; the owner counts each step it runs.
  long long steps = 0;

 private:
  int stepsPerSecond_;
  double warmUp_, maxCatchUp_;
  bool started_ = false;
  double start_ = 0.0;
};

}  // namespace ocean
