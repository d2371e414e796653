#include <cmath>

#include "scene/hash_noise.h"
#include "scene/mesh_builders.h"
#include "scene/scene_parts.h"

namespace ocean_scene {

Mesh buildRock(const RockParams& params, const std::string& name) {
  Mesh mesh = makeIcosphere(params.subdivisions, name);
  // Each rock samples a different region of the noise so no two look alike.
  const glm::dvec3 offset(static_cast<double>(hash32(params.seed) % 1000U) * 0.37, 11.3,
                          static_cast<double>(hash32(params.seed + 7U) % 1000U) * 0.29);
  for (glm::vec3& p : mesh.positions) {
    const glm::dvec3 unit(p);
    const double bumps = fbm3(unit * 1.8 + offset, 4, params.seed);
    // fbm stays within [-1, 1], so with roughness < 1 the radius never reaches zero.
    const double r = params.radius * (1.0 + params.roughness * bumps);
    p = glm::vec3(unit * r * params.stretch);
  }
  computeSmoothNormals(mesh);
  return mesh;
}

}  // namespace ocean_scene
