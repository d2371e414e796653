#pragma once
// Host-side inputs of the object-caustics scenes the tests and the report run (a glass sphere or
// a metal ring over a plane): caster meshes in GL buffers (what a host's renderer owns) and an
// analytic receiver depth map (a plane seen from the sun, the depth a host shadow pass would
// write), computed in double on the CPU.
#include <epoxy/gl.h>

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

#include <postfx/postfx.h>

namespace ocean::reference {

// A triangle mesh in host-owned buffers: position (float3) + normal (float3), 24-byte stride.
class GlMesh {
 public:
  GlMesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
         const std::vector<std::uint32_t>& indices);
  ~GlMesh();
  GlMesh(const GlMesh&) = delete;
  GlMesh& operator=(const GlMesh&) = delete;

  // The caster description of this mesh under `modelToWorld`.
  postfx::CasterMesh caster(const glm::dmat4& modelToWorld,
                            const postfx::CasterMaterial& material) const;

  GLuint vertexBuffer = 0, indexBuffer = 0;
  std::int64_t vertexCount = 0, indexCount = 0;
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};
};

// UV sphere of `radius` around the origin with exact vertex normals: (slices + 1) x (stacks + 1)
// vertices from the north pole down, two triangles per quad (those at the poles degenerate).
struct UvSphere {
  std::vector<glm::dvec3> positions, normals;
  std::vector<std::uint32_t> indices;
};
UvSphere uvSphere(double radius, int slices, int stacks);
// The same in host-owned GL buffers.
GlMesh makeSphereMesh(double radius, int slices, int stacks);
// Open-topped ring: inner wall (normals toward the axis), outer wall, top and bottom annuli;
// axis y, from y = 0 to `height`.
GlMesh makeRingMesh(double inner, double outer, double height, int segments);
// Axis-aligned cube of half side `half` (normals per face).
GlMesh makeCubeMesh(double half);

// Receiver depth map of the plane y = planeY seen from the sun: orthographic along -towardSun,
// covering a square of half side `halfExtent` (m) around `centre`, forward [-1, 1] depth
// (SunShadowMap::depthConvention 2), GL_DEPTH_COMPONENT32F. Texels whose ray misses the plane
// (or hits it outside [-planeHalf, planeHalf] in x and z, if planeHalf > 0) stay at the far plane.
// `occluder` (xyz centre, w radius), when given: a sphere in front of the plane, as a host's sun
// shadow map holds its casters.
class ReceiverMap {
 public:
  ReceiverMap(const glm::dvec3& towardSun, const glm::dvec3& centre, double halfExtent,
              double planeY, int size, double planeHalf = 0.0,
              const glm::dvec4* occluder = nullptr);
  ~ReceiverMap();
  ReceiverMap(const ReceiverMap&) = delete;
  ReceiverMap& operator=(const ReceiverMap&) = delete;

  postfx::SunShadowMap desc() const;

  GLuint depth = 0;
  glm::dmat4 worldToLightClip{1.0};
  int size = 0;
};

// Receiver depth map of the plane y = planeY (within +-planeHalf in x and z; 0: unbounded) seen
// from a point or spot light at `position`: perspective along unit `axis` over a square of full
// angle `fovDegrees`, near `near` m, far `far` m, forward [0, 1] depth
// (DepthConvention::ForwardZeroToOne), GL_DEPTH_COMPONENT32F, computed in double. Texels whose
// ray misses the plane between the near and far planes stay at the far plane.
class LightReceiverMap {
 public:
  LightReceiverMap(const glm::dvec3& position, const glm::dvec3& axis, double fovDegrees,
                   double planeY, int size, double far = 100.0, double near = 0.05,
                   double planeHalf = 0.0);
  ~LightReceiverMap();
  LightReceiverMap(const LightReceiverMap&) = delete;
  LightReceiverMap& operator=(const LightReceiverMap&) = delete;

  postfx::SunShadowMap desc() const;

  GLuint depth = 0;
  glm::dmat4 worldToLightClip{1.0};
  int size = 0;
};

}  // namespace ocean::reference
