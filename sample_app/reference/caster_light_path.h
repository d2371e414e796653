#pragma once
// A traced photon's way through the frame's glass and metal casters, on their real triangles
// (Embree), with the optics postfx::CasterMaterial's header states, so that the frame reference
// (frame_caustics_reference.h) covers the object caustics the plugin adds:
//   * Refractive, solid: exact unpolarised Fresnel transmittance and Snell refraction where the
//     ray enters and where it leaves (index relative to the medium around the caster), the
//     transmission weight and the tint once per ray, Beer-Lambert absorption along the chord;
//     total internal reflection is followed (the plugin drops such rays). Dispersion: each
//     channel traced alone with index ior + (c - 1) (ior - 1) 0.025 dispersion (R, G, B).
//   * Refractive, thin-walled: the ray keeps its direction through the whole caster and loses
//     both Fresnel reflections of its first surface, times transmission and tint; no absorption.
//   * Reflective: one Schlick bounce (F0 = reflectance) on each face the ray meets from outside.
//   * Roughness: the outgoing ray deflected by a Gaussian of standard deviation roughness^2
//     radians on each axis across it (after the exit of a refractive caster, at each bounce).
// The light the casters reflect off glass or send back out of the water is not followed.
#include <functional>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include <postfx/casters.h>

#include "embree_scene.h"

namespace postfx::water {
class GaussianRandom;
}

namespace ocean::reference {

// Per mesh of the EmbreeScene: its caster material, or none for an ordinary opaque surface.
using CasterMaterials = std::vector<std::optional<postfx::CasterMaterial>>;

struct CasterPathDesc {
  double waterIor = 1.333;   // the medium around casters below `waterLevel`; air above it
  double waterLevel = 0.0;   // in the scene's (camera-relative) frame
  int maxInteractions = 12;  // surface events per path, internal reflections included
};

struct CasterLanding {
  glm::dvec3 point;   // on an ordinary surface, camera-relative
  glm::dvec3 normal;  // that surface's shading normal there
  glm::dvec3 weight;  // the photon's flux weight that arrives, per channel
  glm::dvec3 from;    // where its last straight segment began (the caster surface it left)
};

// The ray from + t dir has hit caster mesh hit.mesh (materials[hit.mesh] set) carrying `weight`
// per channel. Calls `land` for each part of its light that reaches an ordinary surface facing
// it (three parts at most, one per channel, through dispersive glass). Deterministic for a
// given state of `random`.
void followThroughCasters(const EmbreeScene& scene, const CasterMaterials& materials,
                          const CasterPathDesc& desc, const glm::dvec3& from, const glm::dvec3& dir,
                          const RayHit& hit, const glm::dvec3& weight,
                          postfx::water::GaussianRandom& random,
                          const std::function<void(const CasterLanding&)>& land);

// Whether `mesh` is a caster in `materials` (an empty list: no casters at all).
inline bool isCaster(const CasterMaterials& materials, int mesh) {
  return mesh >= 0 && static_cast<size_t>(mesh) < materials.size() &&
         materials[static_cast<size_t>(mesh)].has_value();
}

}  // namespace ocean::reference
