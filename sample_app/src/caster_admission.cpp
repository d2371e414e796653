#include "caster_admission.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "gpu_scene.h"

namespace ocean {

postfx::CasterMaterial casterMaterial(const ocean_scene::Material& m) {
  postfx::CasterMaterial out;
  if (!m.isRefractive()) {
    out.type = postfx::CasterMaterialType::Reflective;
    out.reflectance = glm::clamp(m.baseColor, glm::vec3(0.0f), glm::vec3(1.0f));
    return out;
  }
  out.type = postfx::CasterMaterialType::Refractive;
  out.ior = std::clamp(m.ior, 1.0f, 3.0f);
  if (std::isfinite(m.attenuationDistance) && m.attenuationDistance > 0.0f) {
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
    // casterMaterial clamps the IOR to the plugin's [1, 3]; say so once per material.
    if (material.isRefractive() && material.ior > 3.0f &&
        clampWarned.insert(materialIndex).second) {
      char ior[32];
      std::snprintf(ior, sizeof ior, "%.3g", double(material.ior));
      warnings.push_back(instance.name + ": material '" + material.name + "' ior " + ior +
                         " is clamped to 3, the plugin's limit");
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
