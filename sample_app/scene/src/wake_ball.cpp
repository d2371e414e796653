#include "scene/wake_ball.h"

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builders.h"

namespace ocean_scene {

void addWakeBall(Model& model, double radius) {
  Material orange;
  orange.name = "wake_ball";
  orange.baseColor = {0.80f, 0.22f, 0.04f};  // a float's safety orange, linear
  orange.metallic = 0.0f;
  orange.roughness = 0.5f;
  model.materials.push_back(orange);
  Mesh ball = makeIcosphere(3, kWakeBallName);
  ball.material = std::uint32_t(model.materials.size() - 1);
  addMeshInstance(model, std::move(ball), glm::scale(glm::mat4(1.0f), glm::vec3(float(radius))),
                  kWakeBallName);
}

}  // namespace ocean_scene
