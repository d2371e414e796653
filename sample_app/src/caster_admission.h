#pragma once
// Which of the scene's glass and metal instances the plugin's object caustics receive. The
// plugin refuses a whole frame for one caster it cannot use; the sample instead leaves such a
// caster out, with a warning naming it, so one odd node in a user's file does not stop the
// render.

#include <string>
#include <vector>

#include <postfx/casters.h>
#include <scene/model.h>

namespace ocean {

// glTF material -> the plugin's. Transmission on a mostly dielectric surface (metallic < 0.5)
// means glass: KHR_materials_ior, transmissionFactor x (1 - metallic) as the transmission
// weight, the base colour as the tint of transmitted light, KHR_materials_volume's attenuation
// as Beer-Lambert absorption, thicknessFactor 0 (or no volume) as thin-walled,
// KHR_materials_dispersion, roughness. Otherwise a mirror: metal whose base colour is its
// reflectance at normal incidence (glTF metallic-roughness), or, for transmissive glass with
// ior 0 (the spec's infinite IOR), a white mirror.
postfx::CasterMaterial casterMaterial(const ocean_scene::Material& material);

// "ior 4 is clamped to 3, the plugin's limit" (or the dispersion's) when casterMaterial had
// to clamp a field to the plugin's range; "" when nothing was clamped.
std::string clampedFields(const ocean_scene::Material& material);

// Why the plugin would refuse this instance as a caster (its CasterMesh checks on the
// transform and material), or "" when it would accept it.
std::string casterRefusal(const ocean_scene::Material& material, const glm::mat4& transform);

// Clears Instance::castsCaustics on every caster the plugin would refuse, and on every caster
// past the first postfx::kMaxCasters (scene order: the sample's own models first, then --model
// files in order). One warning per refused instance ("<instance>: casts no caustics, <reason>") and
// one for the budget, so nothing is dropped silently.
void admitCasters(ocean_scene::Model& scene, std::vector<std::string>& warnings);

}  // namespace ocean
