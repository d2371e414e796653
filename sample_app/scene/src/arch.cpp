#include <algorithm>
#include <cmath>

#include "scene/hash_noise.h"
#include "scene/mesh_builders.h"
#include "scene/scene_features.h"
#include "scene/scene_parts.h"

namespace ocean_scene {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kAlongSegments = 120;
constexpr int kAroundSegments = 28;
constexpr double kBumpAmplitude = 0.22;  // metres; enough to read as rock, not to pierce it
constexpr double kBumpFrequency = 0.55;  // per metre

}  // namespace

Mesh buildArch(double footDepth, std::uint32_t seed) {
  using namespace features;
  Mesh mesh;
  mesh.name = "rock_arch";
  const double radius = kArchRadius;
  // Angular extension below the feet: the centreline dips footDepth below y = 0.
  const double extra = std::asin(std::clamp(footDepth / radius, 0.0, 0.9));
  const double theta0 = -extra, theta1 = kPi + extra;
  const auto along = static_cast<std::uint32_t>(kAlongSegments);
  const auto around = static_cast<std::uint32_t>(kAroundSegments);
  for (std::uint32_t i = 0; i <= along; ++i) {
    const double theta = theta0 + (theta1 - theta0) * static_cast<double>(i) / along;
    const glm::dvec3 radial(std::cos(theta), std::sin(theta), 0.0);
    const glm::dvec3 centre = radius * radial;
    for (std::uint32_t j = 0; j < around; ++j) {
      const double phi = 2.0 * kPi * static_cast<double>(j) / around;
      // Elliptical cross-section in the plane normal to the centreline (radial, z).
      const glm::dvec3 offset = kArchHalfThickness * std::cos(phi) * radial +
                                kArchHalfDepth * std::sin(phi) * glm::dvec3(0.0, 0.0, 1.0);
      const glm::dvec3 outward =
          glm::normalize(std::cos(phi) / kArchHalfThickness * radial +
                         std::sin(phi) / kArchHalfDepth * glm::dvec3(0.0, 0.0, 1.0));
      const glm::dvec3 p = centre + offset;
      const double bump = kBumpAmplitude * fbm3(p * kBumpFrequency, 3, seed);
      mesh.positions.emplace_back(p + bump * outward);
    }
  }
  // (along x around) points outward, so (a, c, b) is counter-clockwise seen from outside.
  for (std::uint32_t i = 0; i < along; ++i) {
    for (std::uint32_t j = 0; j < around; ++j) {
      const std::uint32_t jn = (j + 1) % around;
      const std::uint32_t a = i * around + j, b = i * around + jn;
      const std::uint32_t c = (i + 1) * around + j, d = (i + 1) * around + jn;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  }
  // Caps close the tube at both (buried) ends so the mesh is watertight.
  for (int end = 0; end < 2; ++end) {
    const std::uint32_t ring = end == 0 ? 0 : along;
    const double theta = end == 0 ? theta0 : theta1;
    const auto centreIndex = static_cast<std::uint32_t>(mesh.positions.size());
    mesh.positions.emplace_back(radius * glm::dvec3(std::cos(theta), std::sin(theta), 0.0));
    for (std::uint32_t j = 0; j < around; ++j) {
      const std::uint32_t a = ring * around + j, b = ring * around + (j + 1) % around;
      if (end == 0) {
        mesh.indices.insert(mesh.indices.end(), {centreIndex, a, b});
      } else {
        mesh.indices.insert(mesh.indices.end(), {centreIndex, b, a});
      }
    }
  }
  computeSmoothNormals(mesh);
  return mesh;
}

}  // namespace ocean_scene
