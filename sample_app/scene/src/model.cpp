#include "scene/model.h"

#include <utility>

namespace ocean_scene {

void appendModel(Model& dst, const Model& src, const glm::mat4& transform) {
  const auto meshBase = static_cast<std::uint32_t>(dst.meshes.size());
  const auto materialBase = static_cast<std::uint32_t>(dst.materials.size());
  dst.materials.insert(dst.materials.end(), src.materials.begin(), src.materials.end());
  for (Mesh mesh : src.meshes) {
    mesh.material += materialBase;
    dst.meshes.push_back(std::move(mesh));
  }
  for (Instance instance : src.instances) {
    instance.mesh += meshBase;
    instance.transform = transform * instance.transform;
    dst.instances.push_back(std::move(instance));
  }
}

std::uint32_t addMeshInstance(Model& model, Mesh mesh, const glm::mat4& transform,
                              const std::string& instanceName) {
  const auto index = static_cast<std::uint32_t>(model.meshes.size());
  model.meshes.push_back(std::move(mesh));
  model.instances.push_back(Instance{index, transform, instanceName});
  return index;
}

std::size_t triangleCount(const Model& model) {
  std::size_t count = 0;
  for (const Instance& instance : model.instances) {
    if (instance.mesh < model.meshes.size())
      count += model.meshes[instance.mesh].indices.size() / 3;
  }
  return count;
}

std::size_t vertexCount(const Model& model) {
  std::size_t count = 0;
  for (const Instance& instance : model.instances) {
    if (instance.mesh < model.meshes.size()) count += model.meshes[instance.mesh].positions.size();
  }
  return count;
}

}  // namespace ocean_scene
