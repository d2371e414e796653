#include "caster_admission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "gpu_scene.h"

namespace ocean {

postfx::CasterMaterial casterMaterial(const ocean_scene::Material& m) {
  postfx::CasterMaterial out;
  out.roughness = std::clamp(m.roughness, 0.0f, 1.0f);
  // glTF: the metal lobe takes `metallic` of the light and transmission acts only on the
  // dielectric rest; the plugin has one lobe per caster, so a mostly metal surface is a mirror.
  // ior 0 (KHR_materials_ior's infinite IOR) makes the Fresnel term 1: all light is reflected,
  // uncoloured, none transmitted.
  const bool metal = m.metallic >= 0.5f;
  if (!m.isRefractive() || metal || m.ior == 0.0f) {
    out.type = postfx::CasterMaterialType::Reflective;
    out.reflectance =
        metal ? glm::clamp(m.baseColor, glm::vec3(0.0f), glm::vec3(1.0f)) : glm::vec3(1.0f);
    return out;
  }
  out.type = postfx::CasterMaterialType::Refractive;
  out.ior = std::clamp(m.ior, 1.0f, 3.0f);
  out.transmission = std::clamp(m.transmission * (1.0f - m.metallic), 0.0f, 1.0f);
  out.tint = glm::clamp(m.baseColor, glm::vec3(0.0f), glm::vec3(1.0f));
  out.dispersion = std::clamp(m.dispersion, 0.0f, postfx::kMaxCasterDispersion);
  // KHR_materials_volume: thicknessFactor 0 (or no volume at all) is a thin-walled surface,
  // with no volume to absorb in.
  out.thinWalled = !(m.thickness > 0.0f);
  if (!out.thinWalled && std::isfinite(m.attenuationDistance) && m.attenuationDistance > 0.0f) {
    const glm::vec3 colour = glm::clamp(m.attenuationColor, glm::vec3(1e-4f), glm::vec3(1.0f));
    out.absorption = -glm::log(colour) / m.attenuationDistance;
  }
  return out;
}

std::string casterRefusal(const ocean_scene::Material& material, const glm::mat4& transform) {
  // The limits are the plugin's CasterMesh checks (postfx/casters.h, object-caustics validation).
  const glm::dmat4 m(transform);
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return "its transform is not finite";
    }
  }
  if (!(std::abs(glm::determinant(glm::dmat3(m))) > 1e-30)) {
    return "its transform is not invertible (scale 0)";
  }
  const postfx::CasterMaterial caster = casterMaterial(material);
  const glm::vec3 a = caster.absorption;
  const float worst = std::max({a.x, a.y, a.z});
  if (!(worst <= 1e4f) || !(std::min({a.x, a.y, a.z}) >= 0.0f)) {
    char numbers[96];
    std::snprintf(numbers, sizeof numbers, "%.3g /m (attenuationDistance %.3g m)", double(worst),
                  double(material.attenuationDistance));
    return "material '" + material.name + "' absorbs " + numbers +
           "; the plugin takes at most 1e4 /m";
  }
  return "";
}

std::string clampedFields(const ocean_scene::Material& material) {
  if (casterMaterial(material).type != postfx::CasterMaterialType::Refractive) return "";
  char text[160] = "";
  if (material.ior > 3.0f) {
    std::snprintf(text, sizeof text, "ior %.3g is clamped to 3, the plugin's limit",
                  double(material.ior));
  } else if (material.dispersion > postfx::kMaxCasterDispersion) {
    std::snprintf(text, sizeof text, "dispersion %.3g is clamped to %.3g, the plugin's limit",
                  double(material.dispersion), double(postfx::kMaxCasterDispersion));
  }
  return text;
}

void admitCasters(ocean_scene::Model& scene, std::vector<std::string>& warnings) {
  int admitted = 0;
  int overBudget = 0;
  std::set<std::uint32_t> clampWarned;
  std::string firstOverBudget;
  for (ocean_scene::Instance& instance : scene.instances) {
    if (!instance.castsCaustics || instance.mesh >= scene.meshes.size()) continue;
    const std::uint32_t materialIndex = scene.meshes[instance.mesh].material;
    if (materialIndex >= scene.materials.size()) continue;
    const ocean_scene::Material& material = scene.materials[materialIndex];
    if (!isCausticCaster(material)) continue;
    const std::string refusal = casterRefusal(material, instance.transform);
    if (!refusal.empty()) {
      instance.castsCaustics = false;
      warnings.push_back(instance.name + ": casts no caustics, " + refusal);
      continue;
    }
    // casterMaterial clamps what the plugin cannot take; say so once per material.
    const std::string clamped = clampedFields(material);
    if (!clamped.empty() && clampWarned.insert(materialIndex).second) {
      warnings.push_back(instance.name + ": material '" + material.name + "' " + clamped);
    }
    if (admitted == postfx::kMaxCasters) {
      instance.castsCaustics = false;
      if (overBudget++ == 0) firstOverBudget = instance.name;
      continue;
    }
    ++admitted;
  }
  if (overBudget > 0) {
    warnings.push_back(
        std::to_string(admitted + overBudget) + " glass/metal instances but the plugin takes " +
        std::to_string(postfx::kMaxCasters) + " casters: the last " + std::to_string(overBudget) +
        " (from '" + firstOverBudget + "' on) are drawn but cast no caustics");
  }
}

}  // namespace ocean
