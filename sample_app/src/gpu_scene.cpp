#include "gpu_scene.h"

#include <glm/gtc/type_ptr.hpp>

#include <glkit/program.h>

namespace ocean {

bool isCausticCaster(const ocean_scene::Material& material) {
  return material.isRefractive() || material.metallic >= 0.5f;
}

void GpuScene::upload(const ocean_scene::Model& model) {
  for (const ocean_scene::Mesh& mesh : model.meshes) {
    std::vector<glm::vec3> interleaved;
    interleaved.reserve(mesh.positions.size() * 2);
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
      interleaved.push_back(mesh.positions[i]);
      interleaved.push_back(i < mesh.normals.size() ? mesh.normals[i] : glm::vec3(0, 1, 0));
    }
    GpuMesh gpu;
    gpu.vertices = glkit::createBuffer(GLsizeiptr(interleaved.size() * sizeof(glm::vec3)),
                                       interleaved.data(), 0, {});
    gpu.indices = glkit::createBuffer(GLsizeiptr(mesh.indices.size() * sizeof(uint32_t)),
                                      mesh.indices.data(), 0, {});
    gpu.vao = glkit::createVertexArray("scene." + mesh.name);
    const GLuint vao = gpu.vao.id();
    glVertexArrayVertexBuffer(vao, 0, gpu.vertices.id(), 0, 2 * sizeof(glm::vec3));
    glVertexArrayElementBuffer(vao, gpu.indices.id());
    for (GLuint attribute : {0u, 1u}) {
      glEnableVertexArrayAttrib(vao, attribute);
      glVertexArrayAttribFormat(vao, attribute, 3, GL_FLOAT, GL_FALSE,
                                attribute * GLuint(sizeof(glm::vec3)));
      glVertexArrayAttribBinding(vao, attribute, 0);
    }
    gpu.indexCount = GLsizei(mesh.indices.size());
    gpu.vertexCount = GLsizei(mesh.positions.size());
    gpu.boundsMin = glm::vec3(0.0f);
    gpu.boundsMax = glm::vec3(0.0f);
    if (!mesh.positions.empty()) gpu.boundsMin = gpu.boundsMax = mesh.positions[0];
    for (const glm::vec3& p : mesh.positions) {
      gpu.boundsMin = glm::min(gpu.boundsMin, p);
      gpu.boundsMax = glm::max(gpu.boundsMax, p);
    }
    meshes_.push_back(std::move(gpu));
  }
  for (const ocean_scene::Instance& instance : model.instances) {
    const ocean_scene::Mesh& mesh = model.meshes[instance.mesh];
    const bool known = mesh.material < model.materials.size();
    const glm::vec3 albedo = known ? model.materials[mesh.material].baseColor : glm::vec3(0.5f);
    const bool caster = instance.castsCaustics && known &&
                        isCausticCaster(model.materials[mesh.material]) &&
                        meshes_[instance.mesh].indexCount >= 3;
    instances_.push_back({instance.mesh, glm::dmat4(instance.transform), albedo, caster});
    if (caster) {
      const GpuMesh& gpu = meshes_[instance.mesh];
      casters_.push_back({gpu.vertices.id(), gpu.indices.id(), gpu.vertexCount, gpu.indexCount,
                          gpu.boundsMin, gpu.boundsMax, glm::dmat4(instance.transform),
                          model.materials[mesh.material]});
    }
  }
}

void GpuScene::draw(GLuint program, const glm::dvec3& cameraPosition, DrawSet set) const {
  const GLint modelLocation = glGetUniformLocation(program, "modelRelative");
  const GLint normalLocation = glGetUniformLocation(program, "normalMatrix");
  const GLint albedoLocation = glGetUniformLocation(program, "albedo");
  for (const GpuInstance& instance : instances_) {
    if (set == DrawSet::NonCasters && instance.caster) continue;
    glm::dmat4 relative = instance.transform;
    relative[3] -= glm::dvec4(cameraPosition, 0.0);  // in double: far worlds stay precise
    const glm::mat4 model(relative);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    glUniformMatrix4fv(modelLocation, 1, GL_FALSE, glm::value_ptr(model));
    if (normalLocation >= 0)
      glUniformMatrix3fv(normalLocation, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    if (albedoLocation >= 0) glUniform3fv(albedoLocation, 1, glm::value_ptr(instance.albedo));
    const GpuMesh& mesh = meshes_[instance.mesh];
    glBindVertexArray(mesh.vao.id());
    glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

}  // namespace ocean
