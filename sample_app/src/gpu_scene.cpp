#include "gpu_scene.h"

#include <glm/gtc/type_ptr.hpp>

#include <glkit/program.h>

#include <algorithm>
#include <cmath>

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
    ocean_scene::Material material;
    if (known)
      material = model.materials[mesh.material];
    else {
      material.baseColor = glm::vec3(0.5f);
      material.metallic = 0.0f;
    }
    const bool caster = instance.castsCaustics && known && isCausticCaster(material) &&
                        meshes_[instance.mesh].indexCount >= 3;
    instances_.push_back({instance.mesh, glm::dmat4(instance.transform), material, caster});
    if (caster) {
      const GpuMesh& gpu = meshes_[instance.mesh];
      casters_.push_back({gpu.vertices.id(), gpu.indices.id(), gpu.vertexCount, gpu.indexCount,
                          gpu.boundsMin, gpu.boundsMax, glm::dmat4(instance.transform), material});
    }
  }
}

bool GpuScene::inSet(const GpuInstance& instance, DrawSet set) {
  const bool refractive = instance.material.isRefractive();
  switch (set) {
    case DrawSet::All:
      return true;
    case DrawSet::NonCasters:
      return !instance.caster;
    case DrawSet::Opaque:
      return !refractive;
    case DrawSet::Refractive:
      return refractive;
    case DrawSet::Metal:
      return !refractive && instance.material.metallic >= 0.5f;
  }
  return false;
}

bool GpuScene::setTransform(size_t instance, const glm::dmat4& transform) {
  if (instance >= instances_.size() || instances_[instance].caster) return false;
  instances_[instance].transform = transform;
  return true;
}

bool GpuScene::has(DrawSet set) const {
  for (const GpuInstance& instance : instances_)
    if (inSet(instance, set)) return true;
  return false;
}

void GpuScene::draw(GLuint program, const glm::dvec3& cameraPosition, DrawSet set) const {
  const GLint modelLocation = glGetUniformLocation(program, "modelRelative");
  const GLint normalLocation = glGetUniformLocation(program, "normalMatrix");
  const GLint albedoLocation = glGetUniformLocation(program, "albedo");
  const GLint baseColorLocation = glGetUniformLocation(program, "baseColor");
  const GLint iorLocation = glGetUniformLocation(program, "materialIor");
  const GLint roughnessLocation = glGetUniformLocation(program, "roughness");
  const GLint absorptionLocation = glGetUniformLocation(program, "glassAbsorption");
  const GLint detailLocation = glGetUniformLocation(program, "surfaceDetail");
  const GLint tileLocation = glGetUniformLocation(program, "tileJoints");
  for (const GpuInstance& instance : instances_) {
    if (!inSet(instance, set)) continue;
    const ocean_scene::Material& material = instance.material;
    glm::dmat4 relative = instance.transform;
    relative[3] -= glm::dvec4(cameraPosition, 0.0);  // in double: far worlds stay precise
    const glm::mat4 model(relative);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    glUniformMatrix4fv(modelLocation, 1, GL_FALSE, glm::value_ptr(model));
    if (normalLocation >= 0)
      glUniformMatrix3fv(normalLocation, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    if (albedoLocation >= 0) {
      const glm::vec3 diffuse =
          material.baseColor * (1.0f - glm::clamp(material.metallic, 0.0f, 1.0f));
      glUniform3fv(albedoLocation, 1, glm::value_ptr(diffuse));
    }
    if (baseColorLocation >= 0)
      glUniform3fv(baseColorLocation, 1, glm::value_ptr(material.baseColor));
    // KHR_materials_ior's 0 is an infinite IOR: a mirror.
    if (iorLocation >= 0) glUniform1f(iorLocation, material.ior > 0.0f ? material.ior : 1e4f);
    if (roughnessLocation >= 0) glUniform1f(roughnessLocation, material.roughness);
    if (detailLocation >= 0) glUniform1f(detailLocation, material.proceduralRock ? 1.0f : 0.0f);
    if (tileLocation >= 0) {
      const bool tiled = material.tilePitch > 0.0f && material.tileJoint > 0.0f;
      glUniform2f(tileLocation, tiled ? material.tilePitch : 0.0f,
                  tiled ? 0.5f * std::min(material.tileJoint, material.tilePitch) : 0.0f);
    }
    if (absorptionLocation >= 0) {
      // Beer-Lambert: attenuationColor remains after attenuationDistance metres.
      glm::vec3 sigma(0.0f);
      if (std::isfinite(material.attenuationDistance) && material.attenuationDistance > 0.0f)
        sigma = -glm::log(glm::max(material.attenuationColor, glm::vec3(1e-4f))) /
                material.attenuationDistance;
      glUniform3fv(absorptionLocation, 1, glm::value_ptr(sigma));
    }
    const GpuMesh& mesh = meshes_[instance.mesh];
    glBindVertexArray(mesh.vao.id());
    glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
}

}  // namespace ocean
