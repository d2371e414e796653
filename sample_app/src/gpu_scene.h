#pragma once
// The scene's meshes on the GPU: one vertex/index buffer pair per mesh, drawn per instance
// with camera-relative transforms (the translation is taken against the camera in double).
#include <epoxy/gl.h>

#include <glkit/handle.h>
#include <glm/glm.hpp>

#include <vector>

#include <scene/model.h>

namespace ocean {

// Glass and metal instances: what the plugin's object caustics draw from the sun (glTF
// transmission > 0, or metallic >= 0.5).
bool isCausticCaster(const ocean_scene::Material& material);

// One caster as the plugin needs it: the host's own buffers (position + normal, 24-byte
// stride, uint32 indices), its model bounds, world transform and material.
struct CasterInstance {
  GLuint vertices = 0, indices = 0;
  GLsizei vertexCount = 0, indexCount = 0;
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
  glm::dmat4 transform{1.0};
  ocean_scene::Material material;
};

class GpuScene {
 public:
  // All: every instance (shadow maps). NonCasters: without the caustic casters (the receiver
  // map the plugin intersects with). Opaque: without the refractive instances (the G-buffer:
  // glass is drawn forward over the lit frame, as deferred engines draw transparency).
  // Refractive: only those. Metal: only metallic (>= 0.5) instances.
  enum class DrawSet { All, NonCasters, Opaque, Refractive, Metal };

  void upload(const ocean_scene::Model& model);
  // Draws the set's instances with `program` bound; sets the uniforms it has of modelRelative,
  // normalMatrix, albedo (the diffuse albedo: baseColor * (1 - metallic), glTF's), and for the
  // forward passes baseColor, materialIor, roughness and glassAbsorption (1/m, from
  // KHR_materials_volume).
  void draw(GLuint program, const glm::dvec3& cameraPosition, DrawSet set = DrawSet::All) const;
  bool has(DrawSet set) const;
  // Moves instance `instance` (its index in the uploaded Model::instances) to `transform`; false
  // for an index out of range or a caustic caster (the plugin's caster list is fixed at upload).
  bool setTransform(size_t instance, const glm::dmat4& transform);
  const std::vector<CasterInstance>& casters() const { return casters_; }

 private:
  struct GpuMesh {
    glkit::VertexArray vao;
    glkit::Buffer vertices, indices;
    GLsizei indexCount = 0, vertexCount = 0;
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
  };
  struct GpuInstance {
    size_t mesh;
    glm::dmat4 transform;
    ocean_scene::Material material;
    bool caster;
  };
  static bool inSet(const GpuInstance& instance, DrawSet set);
  std::vector<GpuMesh> meshes_;
  std::vector<GpuInstance> instances_;
  std::vector<CasterInstance> casters_;
};

}  // namespace ocean
