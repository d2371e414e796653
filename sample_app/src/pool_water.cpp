#include "pool_water.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace ocean {

std::unique_ptr<PoolWater> PoolWater::create(const ocean_scene::PoolSceneParams& pool,
                                             const ocean_scene::Model& scene, std::string& error) {
  std::unique_ptr<PoolWater> water(new PoolWater());
  water->pool_ = pool;
  water->script_.poolSize = pool.size;
  water->script_.sphereRadius = pool.sphereRadius;
  bool found = false;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    if (scene.instances[i].name == ocean_scene::kPoolSphereName) {
      water->sphereInstance_ = i;
      found = true;
    }
  }
  if (!found) {
    error = "pool: the scene has no instance named " + std::string(ocean_scene::kPoolSphereName);
    return nullptr;
  }
  RippleDesc desc;
  desc.resolution = 256;
  desc.size = pool.size;
  water->sim_ = RippleSimulation::create(desc, error);
  if (!water->sim_) return nullptr;
  water->clock_ = std::make_unique<SimulationClock>(water->sim_->stepsPerSecond(), kWarmUpSeconds,
                                                    kMaxCatchUpSeconds);
  postfx::LocalWater region;
  region.centre = glm::dvec2(0.0);  // the pool is centred on the origin (pool_scene.h)
  region.size = pool.size;
  region.rotation = 0.0;
  region.mode = postfx::LocalWaterMode::Replace;  // a pool is water of its own
  region.edgeBlend = 0.0f;                        // its walls hide the edge
  // Twice the simulation's 256 texels: against the traced pool the pattern correlates 0.949 at
  // 640x360 and 0.947 at 1280x720, against 0.929 and 0.892 at 256 (docs/measurements.md,
  // "Local water"); 3.5x the cost on llvmpipe (a GPU rasterises 2 M triangles in well under
  // a millisecond).
  region.gridResolution = 512;
  // The floor on the deepest layer, exactly (postfx/local_water.h).
  region.maxDepth = float(pool.depth);
  water->regions_ = {region};
  return water;
}

bool PoolWater::update(double seconds, std::string& error) {
  if (!std::isfinite(seconds)) {
    error = "pool: the frame's time is not finite";
    return false;
  }
  SimulationClock& clock = *clock_;
  if (clock.needsRestart(seconds)) {
    clock.restart(seconds);
    sim_->reset();
    sphere_ = sphereCentre(script_, clock.timeAt(0));
  }
  const long long target = clock.stepsAt(seconds);
  const double radius = pool_.sphereRadius;
  for (; clock.steps < target; ++clock.steps) {
    const double from = clock.timeAt(clock.steps), to = clock.timeAt(clock.steps + 1);
    for (const ScriptedDrop& drop : dropsBetween(script_, from, to))
      sim_->addDrop(drop.centre, drop.radius, drop.strength);
    // The pool's local axes are the world's (rotation 0, centre at the origin): local (u, y, v)
    // is world (x, y, z).
    const glm::dvec3 next = sphereCentre(script_, to);
    sim_->moveSphere(sphere_, next, radius);
    sphere_ = next;
    sim_->step(1);
  }
  regions_[0].texture = {sim_->texture(), GL_RGBA32F};
  const glm::dmat4 ball =
      glm::scale(glm::translate(glm::dmat4(1.0), sphere_), glm::dvec3(pool_.sphereRadius));
  moves_ = {InstanceMove{sphereInstance_, ball}};
  return true;
}

bool PoolWater::addDrop(glm::dvec2 worldXZ) {
  const glm::dvec2 half = pool_.size * 0.5;
  if (!(std::abs(worldXZ.x) <= half.x && std::abs(worldXZ.y) <= half.y)) return false;
  return sim_->addDrop(worldXZ, kClickRadius, kClickStrength);
}

}  // namespace ocean
