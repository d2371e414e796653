#include "local_light_launch.h"

#include <algorithm>
#include <cmath>

#include "caster_light_path.h"
#include "core/shared_math.h"  // the plugin's own spot cone (shaders/postfx)

namespace ocean::reference {
namespace {

constexpr double kPi = 3.141592653589793;
// The noise unit never drops below this share of the median direct light (as the sun's floor,
// a fifth of flat water's light).
constexpr double kDirectFloorShare = 0.2;

}  // namespace

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const size_t k = std::min(values.size() - 1,
                            static_cast<size_t>(q * static_cast<double>(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<long>(k), values.end());
  return values[k];
}

double spotFactor(const TracedLight& light, const glm::dvec3& dir) {
  if (!light.spot) return 1.0;
  const double angle = std::acos(std::clamp(glm::dot(dir, light.axis), -1.0, 1.0));
  return double(postfx::shared::spotConeFalloff(static_cast<float>(angle),
                                                static_cast<float>(light.outerHalfAngle),
                                                static_cast<float>(light.innerHalfAngle)));
}

std::vector<LightCap> planLightCaps(const EmbreeScene& scene, const FrameReceivers& receivers,
                                    const FrameTraceDesc& desc,
                                    const std::vector<double>& radiusSquared,
                                    std::vector<double>& localDirect,
                                    std::vector<std::uint8_t>& casterShadow,
                                    std::vector<double>& localUnit, double& directMedian) {
  const size_t count = receivers.size();
  std::vector<LightCap> caps;
  localDirect.assign(count, 0.0);
  const double level = receivers.level - receivers.camera.y;
  for (const TracedLight& light : desc.lights) {
    const glm::dvec3 position = light.position - receivers.camera;
    if (!(position.y < level)) continue;  // above the water: not traced
    const double absorption =
        (desc.waterAbsorption.x + desc.waterAbsorption.y + desc.waterAbsorption.z) / 3.0;
    const double intensity = (light.intensity.x + light.intensity.y + light.intensity.z) / 3.0;
    for (size_t i = 0; i < count; ++i) {
      if (!receivers.valid[i] || !(receivers.position[i].y < level)) continue;
      const glm::dvec3 toLight = position - receivers.position[i];
      const double d = glm::length(toLight);
      const double cosN = glm::dot(receivers.normal[i], toLight) / std::max(d, 1e-9);
      const double spot = spotFactor(light, -toLight / std::max(d, 1e-9));
      if (!(cosN > 0.0) || !(spot > 0.0)) continue;
      const double direct = intensity * spot * cosN / (d * d) * std::exp(-absorption * d);
      localDirect[i] += direct;
      const glm::dvec3 from =
          receivers.position[i] + receivers.normal[i] * std::max(1e-3, 1e-4 * glm::length(toLight));
      RayHit hit;
      if (scene.intersect(from, toLight / d, 0.0, d, hit) && isCaster(desc.casters, hit.mesh))
        casterShadow[i] = 1;
    }
    for (size_t mesh = 0; mesh < desc.casters.size() && mesh < scene.meshCount(); ++mesh) {
      if (!desc.casters[mesh]) continue;
      LightCap cap;
      double radius = 0.0;
      glm::dvec3 centre;
      scene.meshBoundingSphere(mesh, centre, radius);
      const double distance = glm::length(centre - position);
      if (!(radius > 0.0) || !(distance > radius * 1.001) || distance > light.range) continue;
      cap.light = &light;
      cap.position = position;
      cap.mesh = static_cast<int>(mesh);
      cap.axis = (centre - position) / distance;
      const glm::dvec3 ref = std::abs(cap.axis.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
      cap.u = glm::normalize(glm::cross(ref, cap.axis));
      cap.v = glm::cross(cap.axis, cap.u);
      cap.cosHalf = std::sqrt(1.0 - (radius / distance) * (radius / distance));
      cap.solidAngle = 2.0 * kPi * (1.0 - cap.cosHalf);
      // Photons per steradian that the kernels behind the caster need for kernelPhotons
      // each under unfocused light: a kernel of radius r at distance d facing the light at
      // cos c spans pi r^2 c / d^2 steradians. The 99th percentile of them: the noise
      // target is a 99th percentile too.
      std::vector<double> need;
      for (size_t i = 0; i < count; ++i) {
        if (!receivers.valid[i]) continue;
        const glm::dvec3 out = receivers.position[i] - position;
        const double d = glm::length(out);
        if (!(d > distance - radius) || glm::dot(out, cap.axis) < cap.cosHalf * d) continue;
        const double c = std::max(std::abs(glm::dot(receivers.normal[i], out)) / d, 0.25);
        need.push_back(desc.kernelPhotonsPerBatch * d * d / (kPi * radiusSquared[i] * c));
      }
      if (need.empty()) continue;  // nothing the camera sees lies behind it
      const double photons =
          std::clamp(cap.solidAngle * quantile(need, 0.99), 1e4,
                     static_cast<double>(std::max<std::uint64_t>(desc.maxLightPhotonsPerBatch, 1)));
      cap.strata = static_cast<int>(std::ceil(std::sqrt(photons)));
      cap.index = caps.size();
      caps.push_back(cap);
    }
  }
  // The noise unit: the direct light, at least a fifth of its median over the pixels it
  // reaches (as kNoiseFloor for the sun's).
  std::vector<double> reached;
  for (double d : localDirect)
    if (d > 0.0) reached.push_back(d);
  directMedian = quantile(reached, 0.5);
  const double floor = reached.empty() ? 1.0 : kDirectFloorShare * directMedian;
  localUnit.resize(count);
  for (size_t i = 0; i < count; ++i) localUnit[i] = std::max(localDirect[i], floor);
  return caps;
}

}  // namespace ocean::reference
