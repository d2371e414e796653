#pragma once
// The traced frame reference's local-light photons (frame_caustics_reference.h, TracedLight):
// for each light under the water and each caster within its range, the cone of directions from
// the light to the caster's bounding sphere, stratified in solid angle, with as many photons per
// batch as the receivers behind the caster need; and each receiver's direct light from the
// lights without casters (the unit their noise is measured in), with the casters' shadows.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "embree_scene.h"
#include "frame_caustics_reference.h"
#include "frame_receivers.h"

namespace ocean::reference {

// The cone of directions from a local light to one caster's bounding sphere, stratified in
// solid angle: strata x strata photons per batch, each of solid angle solidAngle / strata^2.
struct LightCap {
  const TracedLight* light = nullptr;
  glm::dvec3 position{0.0};  // the light, relative to the camera
  int mesh = -1;
  glm::dvec3 axis{0.0}, u{0.0}, v{0.0};  // toward the sphere's centre, and across it
  double cosHalf = 1.0, solidAngle = 0.0;
  int strata = 0;
  std::uint64_t index = 0;  // for the photons' random streams
};

// The spot's cone falloff (the plugin's own) for a ray leaving the light along unit `dir`; 1 for
// a point light.
double spotFactor(const TracedLight& light, const glm::dvec3& dir);

// The caps of every light under the water and caster of desc.casters within its range whose
// cone holds a receiver behind the caster. Fills, per receiver, `localDirect` (the lights'
// direct light without casters, mean of the channels, intensity / m^2), sets `casterShadow` where
// a caster hides a light that would reach it, `directMedian` (localDirect's median over the
// receivers it reaches, 0 for none) and `localUnit` (localDirect, at least a fifth of that
// median). `radiusSquared`: each receiver's kernel radius^2.
std::vector<LightCap> planLightCaps(const EmbreeScene& scene, const FrameReceivers& receivers,
                                    const FrameTraceDesc& desc,
                                    const std::vector<double>& radiusSquared,
                                    std::vector<double>& localDirect,
                                    std::vector<std::uint8_t>& casterShadow,
                                    std::vector<double>& localUnit, double& directMedian);

// The nearest-rank q-quantile of `values` (0 when empty).
double quantile(std::vector<double> values, double q);

}  // namespace ocean::reference
