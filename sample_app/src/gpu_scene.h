#pragma once
// The scene's meshes on the GPU: one vertex/index buffer pair per mesh, drawn per instance
// with camera-relative transforms (the translation is taken against the camera in double).
#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <vector>

#include <scene/model.h>

namespace ocean {

class GpuScene {
 public:
  GpuScene() = default;
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;
  ~GpuScene();

  void upload(const ocean_scene::Model& model);
  // Draws every instance with `program` bound; sets its modelRelative, normalMatrix and albedo
  // uniforms (those it has).
  void draw(GLuint program, const glm::dvec3& cameraPosition) const;

 private:
  struct GpuMesh {
    GLuint vao = 0, vertices = 0, indices = 0;
    GLsizei indexCount = 0;
  };
  struct GpuInstance {
    size_t mesh;
    glm::dmat4 transform;
    glm::vec3 albedo;
  };
  std::vector<GpuMesh> meshes_;
  std::vector<GpuInstance> instances_;
};

}  // namespace ocean
