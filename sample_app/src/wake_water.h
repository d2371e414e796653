#pragma once
// The wake preset's water: a ball towed in a circle across the open sea, and a ripple
// simulation that follows it (one Add region for the plugin, on top of the sea's cascades). The
// region's centre is snapped to whole simulation texels and the simulation's content shifted by
// whole texels when it moves (RippleSimulation::shift), as a camera-following dynamic-wave grid
// does, so the wake stays put in the world; its edges absorb (a sponge) and the plugin fades
// the region into the sea over edgeBlend. The ball pushes water aside as the pool's ball does;
// the equation is non-dispersive, so its wake is a Mach cone (half-angle asin(c / v) = 37
// degrees at 2 m/s for c = 1.2 m/s), not a Kelvin wedge's 19.5 degrees.
#include <memory>
#include <string>
#include <vector>

#include <scene/model.h>

#include "local_water_source.h"
#include "ripple_simulation.h"
#include "simulation_clock.h"

namespace ocean {

struct WakeDesc {
  glm::dvec2 circleCentre{0.0, 4.0};  // m, world x, z of the path's centre
  double circleRadius = 8.0;          // m
  double speed = 2.0;                 // m/s along the circle (counter-clockwise from above)
  double ballRadius = 0.5;            // m
  double ballHeight = -0.1;           // m: the centre's height above the level (floats ~60 % in)
  double regionSize = 16.0;           // m, each side of the simulated square
  int resolution = 256;               // texels a side
  double seaDepth = 12.0;             // m: the plugin's deepest layer (LocalWater::maxDepth)
};

class WakeWater final : public LocalWaterSource {
 public:
  static constexpr double kWarmUpSeconds = 6.0;
  static constexpr double kMaxCatchUpSeconds = 10.0;

  // `scene` holds the ball (scene/wake_ball.h); the GL context must be current.
  static std::unique_ptr<WakeWater> create(const WakeDesc& desc, const ocean_scene::Model& scene,
                                           std::string& error);

  bool update(double seconds, std::string& error) override;
  const std::vector<postfx::LocalWater>& regions() const override { return regions_; }
  bool seaVisible() const override { return true; }
  const std::vector<InstanceMove>& moves() const override { return moves_; }
  bool addDrop(glm::dvec2 worldXZ) override;

  // The ball's centre at `seconds` (world m).
  glm::dvec3 ballAt(double seconds) const;

 private:
  WakeWater() = default;
  // Snaps the region to whole texels around `xz`, shifting the simulation by what it moved.
  void follow(glm::dvec2 xz);

  WakeDesc desc_;
  std::unique_ptr<RippleSimulation> sim_;
  std::unique_ptr<SimulationClock> clock_;
  double texel_ = 0.0;    // m
  glm::i64vec2 cell_{0};  // the region's centre in whole texels of the world
  glm::dvec3 ball_{0.0};
  std::size_t ballInstance_ = 0;
  std::vector<postfx::LocalWater> regions_;
  std::vector<InstanceMove> moves_;
};

}  // namespace ocean
