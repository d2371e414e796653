#include "wake_water.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

#include <scene/wake_ball.h>

namespace ocean {

std::unique_ptr<WakeWater> WakeWater::create(const WakeDesc& desc, const ocean_scene::Model& scene,
                                             std::string& error) {
  std::unique_ptr<WakeWater> water(new WakeWater());
  water->desc_ = desc;
  bool found = false;
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    if (scene.instances[i].name == ocean_scene::kWakeBallName) {
      water->ballInstance_ = i;
      found = true;
    }
  }
  if (!found) {
    error = "wake: the scene has no instance named " + std::string(ocean_scene::kWakeBallName);
    return nullptr;
  }
  RippleDesc ripple;
  ripple.resolution = desc.resolution;
  ripple.size = glm::dvec2(desc.regionSize);
  ripple.damping = 0.2;
  // Open water: what reaches the square's edge leaves (2 m of sponge).
  ripple.absorbingEdge = 2.0;
  water->sim_ = RippleSimulation::create(ripple, error);
  if (!water->sim_) return nullptr;
  water->clock_ = std::make_unique<SimulationClock>(water->sim_->stepsPerSecond(), kWarmUpSeconds,
                                                    kMaxCatchUpSeconds);
  water->texel_ = desc.regionSize / desc.resolution;
  postfx::LocalWater region;
  region.size = glm::dvec2(desc.regionSize);
  region.mode = postfx::LocalWaterMode::Add;  // ripples on top of the sea
  region.edgeBlend = 2.0f;                    // over the sponge, where the wake has died
  region.gridResolution = desc.resolution;
  region.maxDepth = float(desc.seaDepth);
  water->regions_ = {region};
  return water;
}

glm::dvec3 WakeWater::ballAt(double seconds) const {
  // The angle in double, wrapped at a whole turn: a late time keeps its precision.
  const double turn = 2.0 * M_PI * desc_.circleRadius / desc_.speed;  // s
  const double angle = 2.0 * M_PI * std::fmod(seconds, turn) / turn;
  return {desc_.circleCentre.x + desc_.circleRadius * std::cos(angle), desc_.ballHeight,
          desc_.circleCentre.y - desc_.circleRadius * std::sin(angle)};
}

void WakeWater::follow(glm::dvec2 xz) {
  const glm::i64vec2 cell(std::llround(xz.x / texel_), std::llround(xz.y / texel_));
  const glm::i64vec2 moved = cell - cell_;
  // Rotation 0: local u, v are world x, z, so a move of whole world texels is one of texels.
  sim_->shift(glm::ivec2(glm::clamp(moved, glm::i64vec2(-1 << 20), glm::i64vec2(1 << 20))));
  cell_ = cell;
}

bool WakeWater::update(double seconds, std::string& error) {
  if (!std::isfinite(seconds)) {
    error = "wake: the frame's time is not finite";
    return false;
  }
  SimulationClock& clock = *clock_;
  if (clock.needsRestart(seconds)) {
    clock.restart(seconds);
    sim_->reset();
    ball_ = ballAt(clock.timeAt(0));
    cell_ = glm::i64vec2(std::llround(ball_.x / texel_), std::llround(ball_.z / texel_));
  }
  const long long target = clock.stepsAt(seconds);
  for (; clock.steps < target; ++clock.steps) {
    const glm::dvec3 next = ballAt(clock.timeAt(clock.steps + 1));
    follow(glm::dvec2(next.x, next.z));
    // The ball in the region's local frame (u, height, v), both ends about its new centre.
    const glm::dvec3 centre(double(cell_.x) * texel_, 0.0, double(cell_.y) * texel_);
    sim_->moveSphere(ball_ - centre, next - centre, desc_.ballRadius);
    ball_ = next;
    sim_->step(1);
  }
  regions_[0].centre = glm::dvec2(double(cell_.x) * texel_, double(cell_.y) * texel_);
  regions_[0].texture = {sim_->texture(), GL_RGBA32F};
  const glm::dmat4 ball =
      glm::scale(glm::translate(glm::dmat4(1.0), ball_), glm::dvec3(desc_.ballRadius));
  moves_ = {InstanceMove{ballInstance_, ball}};
  return true;
}

bool WakeWater::addDrop(glm::dvec2 worldXZ) {
  const glm::dvec2 local = worldXZ - regions_[0].centre;
  const double half = 0.5 * desc_.regionSize;
  if (!(std::abs(local.x) <= half && std::abs(local.y) <= half)) return false;
  return sim_->addDrop(local, 0.25, -0.04);
}

}  // namespace ocean
