#include "object_caustics_scene.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace ocean::reference {

GlMesh::GlMesh(const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
               const std::vector<std::uint32_t>& indices) {
  std::vector<float> interleaved;
  interleaved.reserve(positions.size() * 6);
  boundsMin = glm::vec3(1e30f);
  boundsMax = glm::vec3(-1e30f);
  for (size_t i = 0; i < positions.size(); ++i) {
    const glm::vec3 p = positions[i], n = normals[i];
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z});
    boundsMin = glm::min(boundsMin, p);
    boundsMax = glm::max(boundsMax, p);
  }
  glCreateBuffers(1, &vertexBuffer);
  glNamedBufferStorage(vertexBuffer, static_cast<GLsizeiptr>(interleaved.size() * 4),
                       interleaved.data(), 0);
  glCreateBuffers(1, &indexBuffer);
  glNamedBufferStorage(indexBuffer, static_cast<GLsizeiptr>(indices.size() * 4), indices.data(), 0);
  vertexCount = static_cast<std::int64_t>(positions.size());
  indexCount = static_cast<std::int64_t>(indices.size());
}

GlMesh::~GlMesh() {
  const GLuint buffers[] = {vertexBuffer, indexBuffer};
  glDeleteBuffers(2, buffers);
}

postfx::CasterMesh GlMesh::caster(const glm::dmat4& modelToWorld,
                                  const postfx::CasterMaterial& material) const {
  postfx::CasterMesh m;
  m.vertexBuffer = vertexBuffer;
  m.indexBuffer = indexBuffer;
  m.indexType = postfx::IndexType::UnsignedInt;
  m.vertexCount = vertexCount;
  m.indexCount = indexCount;
  m.positionOffset = 0;
  m.normalOffset = 12;
  m.stride = 24;
  m.boundsMin = boundsMin;
  m.boundsMax = boundsMax;
  m.modelToWorld = modelToWorld;
  m.material = material;
  return m;
}

UvSphere uvSphere(double radius, int slices, int stacks) {
  UvSphere sphere;
  const double pi = 3.14159265358979323846;
  for (int j = 0; j <= stacks; ++j) {
    const double theta = pi * j / stacks;
    for (int i = 0; i <= slices; ++i) {
      const double phi = 2.0 * pi * i / slices;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::cos(theta),
                         std::sin(theta) * std::sin(phi));
      sphere.normals.push_back(d);
      sphere.positions.push_back(d * radius);
    }
  }
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = j * (slices + 1) + i, b = a + slices + 1;
      sphere.indices.insert(sphere.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  }
  return sphere;
}

GlMesh makeSphereMesh(double radius, int slices, int stacks) {
  const UvSphere sphere = uvSphere(radius, slices, stacks);
  const std::vector<glm::vec3> p(sphere.positions.begin(), sphere.positions.end());
  const std::vector<glm::vec3> n(sphere.normals.begin(), sphere.normals.end());
  return GlMesh(p, n, sphere.indices);
}

GlMesh makeRingMesh(double inner, double outer, double height, int segments) {
  std::vector<glm::vec3> p, n;
  std::vector<std::uint32_t> idx;
  const double pi = 3.14159265358979323846;
  // One quad strip per surface: (radius0, y0) -> (radius1, y1) around the axis, with a normal.
  auto strip = [&](double r0, double y0, double r1, double y1, int normalKind) {
    const std::uint32_t base = static_cast<std::uint32_t>(p.size());
    for (int i = 0; i <= segments; ++i) {
      const double phi = 2.0 * pi * i / segments;
      const glm::dvec3 radial(std::cos(phi), 0.0, std::sin(phi));
      glm::dvec3 normal = normalKind == 0   ? -radial
                          : normalKind == 1 ? radial
                                            : glm::dvec3(0.0, normalKind == 2 ? 1.0 : -1.0, 0.0);
      p.emplace_back(radial * r0 + glm::dvec3(0.0, y0, 0.0));
      p.emplace_back(radial * r1 + glm::dvec3(0.0, y1, 0.0));
      n.emplace_back(normal);
      n.emplace_back(normal);
    }
    for (int i = 0; i < segments; ++i) {
      const std::uint32_t a = base + 2 * i;
      idx.insert(idx.end(), {a, a + 1, a + 2, a + 2, a + 1, a + 3});
    }
  };
  strip(inner, 0.0, inner, height, 0);     // inner wall, facing the axis
  strip(outer, 0.0, outer, height, 1);     // outer wall
  strip(inner, height, outer, height, 2);  // top
  strip(inner, 0.0, outer, 0.0, 3);        // bottom
  return GlMesh(p, n, idx);
}

GlMesh makeCubeMesh(double half) {
  std::vector<glm::vec3> p, n;
  std::vector<std::uint32_t> idx;
  for (int axis = 0; axis < 3; ++axis) {
    for (int s = -1; s <= 1; s += 2) {
      glm::dvec3 normal(0.0);
      normal[axis] = s;
      const glm::dvec3 a = glm::dvec3(normal.y, normal.z, normal.x) * half;
      const glm::dvec3 b = glm::cross(normal, a);
      const std::uint32_t base = static_cast<std::uint32_t>(p.size());
      for (int k = 0; k < 4; ++k) {
        const double u = (k & 1) ? 1.0 : -1.0, v = (k & 2) ? 1.0 : -1.0;
        p.emplace_back(normal * half + a * u + b * v);
        n.emplace_back(normal);
      }
      idx.insert(idx.end(), {base, base + 1, base + 2, base + 2, base + 1, base + 3});
    }
  }
  return GlMesh(p, n, idx);
}

ReceiverMap::ReceiverMap(const glm::dvec3& towardSun, const glm::dvec3& centre, double halfExtent,
                         double planeY, int sizeIn, double planeHalf, const glm::dvec4* occluder)
    : size(sizeIn) {
  const glm::dvec3 l = glm::normalize(towardSun);
  const glm::dvec3 up = std::abs(l.y) > 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  const double range = 4.0 * halfExtent + 100.0;
  const glm::dmat4 view = glm::lookAtRH(centre + l * range * 0.5, centre, up);
  const glm::dmat4 proj =
      glm::orthoRH_NO(-halfExtent, halfExtent, -halfExtent, halfExtent, 0.0, range);
  worldToLightClip = proj * view;
  const glm::dmat4 inverse = glm::inverse(worldToLightClip);
  std::vector<float> texels(static_cast<size_t>(size) * size, 1.0f);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double nx = (x + 0.5) / size * 2.0 - 1.0, ny = (y + 0.5) / size * 2.0 - 1.0;
      glm::dvec4 a = inverse * glm::dvec4(nx, ny, -1.0, 1.0);
      glm::dvec4 b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 pa = glm::dvec3(a) / a.w, pb = glm::dvec3(b) / b.w;
      if (occluder != nullptr) {
        // The sphere's near side, if the texel's ray meets it first (pa -> pb, t in [0, 1]).
        const glm::dvec3 ab = pb - pa, oc = pa - glm::dvec3(*occluder);
        const double qa = glm::dot(ab, ab), qb = glm::dot(oc, ab);
        const double qc = glm::dot(oc, oc) - occluder->w * occluder->w;
        const double disc = qb * qb - qa * qc;
        if (disc > 0.0) {
          const double t = (-qb - std::sqrt(disc)) / qa;
          if (t >= 0.0 && t <= 1.0) {
            texels[static_cast<size_t>(y) * size + x] = static_cast<float>(t);
            continue;
          }
        }
      }
      if (std::abs(pb.y - pa.y) < 1e-12) continue;
      const double t = (planeY - pa.y) / (pb.y - pa.y);
      if (t < 0.0 || t > 1.0) continue;
      const glm::dvec3 hit = pa + (pb - pa) * t;
      if (planeHalf > 0.0 && (std::abs(hit.x) > planeHalf || std::abs(hit.z) > planeHalf)) continue;
      texels[static_cast<size_t>(y) * size + x] = static_cast<float>(t);  // ndc -1..1 -> 0..1
    }
  }
  glCreateTextures(GL_TEXTURE_2D, 1, &depth);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTextureSubImage2D(depth, 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
}

ReceiverMap::~ReceiverMap() {
  glDeleteTextures(1, &depth);
}

postfx::SunShadowMap ReceiverMap::desc() const {
  postfx::SunShadowMap s;
  s.depth = {depth, GL_DEPTH_COMPONENT32F};
  s.worldToLightClip = worldToLightClip;
  s.depthConvention = postfx::DepthConvention::ForwardNegOneToOne;
  s.bias = 0.2f;  // m along the light
  return s;
}

LightReceiverMap::LightReceiverMap(const glm::dvec3& position, const glm::dvec3& axis,
                                   double fovDegrees, double planeY, int sizeIn, double far,
                                   double near, double planeHalf)
    : size(sizeIn) {
  const glm::dvec3 a = glm::normalize(axis);
  const glm::dvec3 up = std::abs(a.y) > 0.99 ? glm::dvec3(0, 0, 1) : glm::dvec3(0, 1, 0);
  worldToLightClip = glm::perspectiveRH_ZO(glm::radians(fovDegrees), 1.0, near, far) *
                     glm::lookAtRH(position, position + a, up);
  const glm::dmat4 inverse = glm::inverse(worldToLightClip);
  std::vector<float> texels(static_cast<size_t>(size) * size, 1.0f);
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double nx = (x + 0.5) / size * 2.0 - 1.0, ny = (y + 0.5) / size * 2.0 - 1.0;
      const glm::dvec4 b = inverse * glm::dvec4(nx, ny, 1.0, 1.0);
      const glm::dvec3 d = glm::dvec3(b) / b.w - position;
      if (std::abs(d.y) < 1e-12) continue;
      const double t = (planeY - position.y) / d.y;
      if (t <= 0.0 || t > 1.0) continue;  // behind the light or past the far plane
      const glm::dvec3 hit = position + d * t;
      if (planeHalf > 0.0 && (std::abs(hit.x) > planeHalf || std::abs(hit.z) > planeHalf)) continue;
      const glm::dvec4 clip = worldToLightClip * glm::dvec4(hit, 1.0);
      const double windowDepth = clip.z / clip.w;
      if (windowDepth >= 0.0)  // not nearer than the near plane
        texels[static_cast<size_t>(y) * size + x] = static_cast<float>(windowDepth);
    }
  }
  glCreateTextures(GL_TEXTURE_2D, 1, &depth);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT32F, size, size);
  glTextureSubImage2D(depth, 0, 0, 0, size, size, GL_DEPTH_COMPONENT, GL_FLOAT, texels.data());
}

LightReceiverMap::~LightReceiverMap() {
  glDeleteTextures(1, &depth);
}

postfx::SunShadowMap LightReceiverMap::desc() const {
  postfx::SunShadowMap s;
  s.depth = {depth, GL_DEPTH_COMPONENT32F};
  s.worldToLightClip = worldToLightClip;
  s.depthConvention = postfx::DepthConvention::ForwardZeroToOne;
  s.bias = 0.05f;  // m along the light
  return s;
}

}  // namespace ocean::reference
