#pragma once
// The pool preset's water: a ripple simulation over the pool's rectangle (one Replace region for
// the plugin, whose walls hide its edge) driven by the pool script's drops and ball, on the
// frame's clock (simulation_clock.h: at rest kWarmUpSeconds before the first frame).
#include <memory>
#include <string>
#include <vector>

#include <scene/model.h>
#include <scene/pool_scene.h>

#include "local_water_source.h"
#include "pool_script.h"
#include "ripple_simulation.h"
#include "simulation_clock.h"

namespace ocean {

class PoolWater final : public LocalWaterSource {
 public:
  static constexpr double kWarmUpSeconds = 4.0;
  static constexpr double kMaxCatchUpSeconds = 10.0;
  // A click's drop: 0.2 m wide, a 4 cm dent.
  static constexpr double kClickRadius = 0.2, kClickStrength = -0.04;

  // `scene` is buildPoolScene(pool)'s (the ball's instance is found by its name); the GL
  // context must be current. nullptr with a message on failure.
  static std::unique_ptr<PoolWater> create(const ocean_scene::PoolSceneParams& pool,
                                           const ocean_scene::Model& scene, std::string& error);

  bool update(double seconds, std::string& error) override;
  const std::vector<postfx::LocalWater>& regions() const override { return regions_; }
  bool seaVisible() const override { return false; }
  const std::vector<InstanceMove>& moves() const override { return moves_; }
  bool addDrop(glm::dvec2 worldXZ) override;

  RippleSimulation& simulation() { return *sim_; }

 private:
  PoolWater() = default;

  ocean_scene::PoolSceneParams pool_;
  PoolScript script_;
  std::unique_ptr<RippleSimulation> sim_;
  std::unique_ptr<SimulationClock> clock_;
  glm::dvec3 sphere_{0.0};
  std::size_t sphereInstance_ = 0;
  std::vector<postfx::LocalWater> regions_;
  std::vector<InstanceMove> moves_;
};

}  // namespace ocean
