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
  postfx::LocalWater region;
  region.centre = glm::dvec2(0.0);  // the pool is centred on the origin (pool_scene.h)
  region.size = pool.size;
  region.rotation = 0.0;
  region.mode = postfx::LocalWaterMode::Replace;  // a pool is water of its own
  region.edgeBlend = 0.0f;                        // its walls hide the edge
  region.gridResolution = 256;
  // The floor on the deepest layer, exactly (postfx/local_water.h).
  region.maxDepth = float(pool.depth);
  water->regions_ = {region};
  return water;
}

double PoolWater::stepTime(long long step) const {
  return start_ + double(step) / double(sim_->stepsPerSecond());
}

void PoolWater::restart(double seconds) {
  sim_->reset();
  start_ = seconds - kWarmUpSeconds;
  steps_ = 0;
  sphere_ = sphereCentre(script_, start_);
  started_ = true;
}

bool PoolWater::update(double seconds, std::string& error) {
  if (!std::isfinite(seconds)) {
    error = "pool: the frame's time is not finite";
    return false;
  }
  const double now = stepTime(steps_);
  if (!started_ || seconds < now - 0.5 * sim_->stepSeconds() || seconds - now > kMaxCatchUpSeconds)
    restart(seconds);
  // Whole steps only: the simulation's time is exact, and frames at the same times give the
  // same water wherever they run.
  const long long target =
      (long long)std::floor((seconds - start_) * double(sim_->stepsPerSecond()) + 1e-6);
  const double radius = pool_.sphereRadius;
  for (; steps_ < target; ++steps_) {
    const double from = stepTime(steps_), to = stepTime(steps_ + 1);
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
