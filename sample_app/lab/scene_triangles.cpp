#include "scene_triangles.h"

#include "caster_admission.h"
#include "gpu_scene.h"

namespace ocean {

std::vector<reference::TriangleMesh> sceneTriangles(const ocean_scene::Model& model) {
  std::vector<reference::TriangleMesh> meshes;
  meshes.reserve(model.instances.size());
  for (const ocean_scene::Instance& instance : model.instances) {
    if (instance.mesh >= model.meshes.size()) continue;
    const ocean_scene::Mesh& mesh = model.meshes[instance.mesh];
    const glm::dmat4 transform(instance.transform);
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(transform)));
    reference::TriangleMesh out;
    out.positions.reserve(mesh.positions.size());
    out.normals.reserve(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      out.positions.push_back(
          glm::dvec3(transform * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0)));
      // GpuScene gives a vertex without a normal (0, 1, 0), as here.
      const glm::dvec3 n =
          i < mesh.normals.size() ? glm::dvec3(mesh.normals[i]) : glm::dvec3(0.0, 1.0, 0.0);
      const glm::dvec3 world = normalMatrix * n;
      const double length = glm::length(world);
      out.normals.push_back(length > 0.0 ? world / length : glm::dvec3(0.0, 1.0, 0.0));
    }
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3)
      out.triangles.emplace_back(mesh.indices[t], mesh.indices[t + 1], mesh.indices[t + 2]);
    meshes.push_back(std::move(out));
  }
  return meshes;
}

reference::CasterMaterials sceneCasterMaterials(const ocean_scene::Model& model) {
  reference::CasterMaterials materials;
  for (const ocean_scene::Instance& instance : model.instances) {
    if (instance.mesh >= model.meshes.size()) continue;  // as sceneTriangles
    const ocean_scene::Mesh& mesh = model.meshes[instance.mesh];
    const bool known = mesh.material < model.materials.size();
    if (instance.castsCaustics && known && isCausticCaster(model.materials[mesh.material]) &&
        mesh.indices.size() >= 3) {
      materials.push_back(casterMaterial(model.materials[mesh.material]));
    } else {
      materials.push_back(std::nullopt);
    }
  }
  return materials;
}

}  // namespace ocean
