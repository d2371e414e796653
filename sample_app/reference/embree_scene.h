#pragma once
// The scene's real triangles in Intel Embree 3, for the traced references: closest hits and
// occlusion of single rays, thread-safe after construction. Vertices are stored relative to an
// origin (the camera), in float as Embree needs them; rays are given and hits returned in
// double in that same relative frame.
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace ocean::reference {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;  // world (m)
  std::vector<glm::dvec3> normals;    // unit, one per position (the G-buffer's normals)
  std::vector<glm::uvec3> triangles;  // indices into positions
};

struct RayHit {
  double t = 0.0;     // distance along the unit direction
  glm::dvec3 normal;  // interpolated vertex normal at the hit, unit (the surface's shading normal)
  int mesh = -1;      // index of the hit mesh in the list EmbreeScene::create was given
};

class EmbreeScene {
 public:
  // Builds the BVH of every mesh, placed relative to `origin`. Null with a message when Embree
  // fails or a mesh is malformed (index out of range, non-finite vertex).
  static std::unique_ptr<EmbreeScene> create(const std::vector<TriangleMesh>& meshes,
                                             const glm::dvec3& origin, std::string& error);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Closest hit of origin + t dir, t in (tNear, tFar); dir unit.
  bool intersect(const glm::dvec3& from, const glm::dvec3& dir, double tNear, double tFar,
                 RayHit& hit) const;
  // Whether anything lies on origin + t dir, t in (tNear, tFar).
  bool occluded(const glm::dvec3& from, const glm::dvec3& dir, double tNear, double tFar) const;

  const glm::dvec3& boundsMin() const { return boundsMin_; }  // relative to the origin
  const glm::dvec3& boundsMax() const { return boundsMax_; }
  size_t triangleCount() const { return triangleCount_; }
  size_t meshCount() const { return meshes_.size(); }
  // Bounding sphere of mesh `mesh`'s vertices (relative to the origin; radius 0 when empty).
  void meshBoundingSphere(size_t mesh, glm::dvec3& centre, double& radius) const;

 private:
  EmbreeScene() = default;
  struct Handles;
  std::unique_ptr<Handles> handles_;
  std::vector<TriangleMesh> meshes_;  // relative positions, for the normals at hits
  glm::dvec3 boundsMin_{0.0}, boundsMax_{0.0};
  size_t triangleCount_ = 0;
};

}  // namespace ocean::reference
