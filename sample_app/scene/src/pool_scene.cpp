#include "scene/pool_scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/mesh_builders.h"

namespace ocean_scene {
namespace {

// The meshes the tiles are sorted into, one material each.
enum Slot : std::uint32_t { kWhiteTile, kGreyTile, kBlueTile, kPaving, kSlots };

// A rectangle of tiled surface: origin + s a + t b for s in [0, lengthA], t in [0, lengthB],
// with a and b unit world axes; its face looks along a x b.
struct Rect {
  glm::vec3 origin, a, b;
  float lengthA, lengthB;
};

void addQuad(Mesh& mesh, glm::vec3 p, glm::vec3 alongA, glm::vec3 alongB, glm::vec3 normal) {
  const auto base = static_cast<std::uint32_t>(mesh.positions.size());
  for (const glm::vec3& q : {p, p + alongA, p + alongA + alongB, p + alongB}) {
    mesh.positions.push_back(q);
    mesh.normals.push_back(normal);
  }
  // Counter-clockwise seen from the normal's side, since a x b is the normal.
  mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
}

// A small integer hash (deterministic everywhere): which tiles are the darker ones.
std::uint32_t hashTile(int i, int j, int face) {
  std::uint32_t h = std::uint32_t(i) * 0x8da6b343u ^ std::uint32_t(j) * 0xd8163841u ^
                    std::uint32_t(face) * 0xcb1ab31fu;
  h ^= h >> 15;
  h *= 0x2c1b3c6du;
  h ^= h >> 12;
  return h;
}

// Tiles on the world's grid of `pitch` (where the renderer draws their joints: Material::
// tilePitch), clipped to the rectangle; `slotOf` picks each tile's mesh from its cell and centre.
template <typename SlotOf>
void addTiled(std::array<Mesh, kSlots>& meshes, const Rect& r, float pitch, SlotOf slotOf) {
  const glm::vec3 normal = glm::normalize(glm::cross(r.a, r.b));
  const float a0 = glm::dot(r.origin, r.a), b0 = glm::dot(r.origin, r.b);
  const int i0 = int(std::floor(a0 / pitch + 1e-4f)), j0 = int(std::floor(b0 / pitch + 1e-4f));
  const int i1 = int(std::ceil((a0 + r.lengthA) / pitch - 1e-4f));
  const int j1 = int(std::ceil((b0 + r.lengthB) / pitch - 1e-4f));
  for (int i = i0; i < i1; ++i) {
    for (int j = j0; j < j1; ++j) {
      const float s0 = std::max(float(i) * pitch - a0, 0.0f);
      const float t0 = std::max(float(j) * pitch - b0, 0.0f);
      const float s1 = std::min(float(i + 1) * pitch - a0, r.lengthA);
      const float t1 = std::min(float(j + 1) * pitch - b0, r.lengthB);
      if (s1 <= s0 || t1 <= t0) continue;
      const glm::vec3 p = r.origin + r.a * s0 + r.b * t0;
      const glm::vec3 centre = r.origin + r.a * (0.5f * (s0 + s1)) + r.b * (0.5f * (t0 + t1));
      addQuad(meshes[slotOf(i, j, centre)], p, r.a * (s1 - s0), r.b * (t1 - t0), normal);
    }
  }
}

Material matte(const char* name, glm::vec3 albedo, float pitch = 0.0f, float joint = 0.0f) {
  Material m;
  m.name = name;
  m.baseColor = albedo;
  m.metallic = 0.0f;
  m.roughness = 0.8f;
  m.tilePitch = pitch;
  m.tileJoint = joint;
  return m;
}

}  // namespace

Model buildPoolScene(const PoolSceneParams& in) {
  PoolSceneParams p = in;
  p.size = glm::clamp(p.size, glm::dvec2(1.0), glm::dvec2(100.0));
  p.depth = std::clamp(p.depth, 1e-2, 20.0);
  p.rimHeight = std::clamp(p.rimHeight, 1e-2, 2.0);
  p.tileSize = std::clamp(p.tileSize, 0.05, 2.0);
  p.groutWidth = std::clamp(p.groutWidth, 0.0, p.tileSize / 4.0);
  p.deckHalfExtent = std::max(p.deckHalfExtent, 0.5 * std::max(p.size.x, p.size.y) + 1.0);
  p.sphereRadius = std::clamp(p.sphereRadius, 1e-2, 0.25 * std::min(p.size.x, p.size.y));

  Model model;
  // Linear albedos: glazed white and grey tiles and a blue waterline band in grout joints,
  // sandstone paving; the renderer draws the joints (Material::tilePitch).
  const float tile = float(p.tileSize), grout = float(p.groutWidth);
  model.materials = {matte("pool_tile_white", {0.78f, 0.80f, 0.82f}, tile, grout),
                     matte("pool_tile_grey", {0.62f, 0.65f, 0.68f}, tile, grout),
                     matte("pool_tile_blue", {0.08f, 0.22f, 0.52f}, tile, grout),
                     matte("pool_paving", {0.58f, 0.53f, 0.46f}, 1.0f, 0.01f)};
  std::array<Mesh, kSlots> meshes;
  const char* const names[kSlots] = {"pool_tiles_white", "pool_tiles_grey", "pool_tiles_blue",
                                     "pool_paving"};
  for (std::uint32_t s = 0; s < kSlots; ++s) {
    meshes[s].name = names[s];
    meshes[s].material = s;
  }

  const float w = float(0.5 * p.size.x), d = float(0.5 * p.size.y);
  const float depth = float(p.depth), rim = float(p.rimHeight), height = depth + rim;
  const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  // The floor, then the four walls (each facing into the pool), tiled from the floor up.
  const std::array<Rect, 5> pool = {
      Rect{{-w, -depth, -d}, z, x, 2 * d, 2 * w}, Rect{{-w, -depth, -d}, y, z, height, 2 * d},
      Rect{{w, -depth, -d}, z, y, 2 * d, height}, Rect{{-w, -depth, -d}, x, y, 2 * w, height},
      Rect{{-w, -depth, d}, y, x, height, 2 * w}};
  // Pools have a dark band along the waterline: tiles whose centre lies within 0.3 m below it.
  for (int face = 0; face < int(pool.size()); ++face) {
    addTiled(meshes, pool[size_t(face)], tile, [face](int i, int j, glm::vec3 centre) {
      if (face > 0 && centre.y > -0.3f) return kBlueTile;
      return hashTile(i, j, face) % 5 == 0 ? kGreyTile : kWhiteTile;
    });
  }
  // The deck at the rim's height, around the pool: metre slabs.
  const float e = float(p.deckHalfExtent);
  const std::array<Rect, 4> deck = {
      Rect{{-e, rim, -e}, z, x, 2 * e, e - w}, Rect{{w, rim, -e}, z, x, 2 * e, e - w},
      Rect{{-w, rim, -e}, z, x, e - d, 2 * w}, Rect{{-w, rim, d}, z, x, e - d, 2 * w}};
  for (const Rect& r : deck) addTiled(meshes, r, 1.0f, [](int, int, glm::vec3) { return kPaving; });

  for (Mesh& mesh : meshes) {
    const std::string name = mesh.name;
    if (!mesh.indices.empty()) addMeshInstance(model, std::move(mesh), glm::mat4(1.0f), name);
  }

  model.materials.push_back(matte("pool_ball", {0.80f, 0.80f, 0.80f}));
  Mesh ball = makeIcosphere(3, kPoolSphereName);
  ball.material = std::uint32_t(model.materials.size() - 1);
  const float r = float(p.sphereRadius);
  addMeshInstance(
      model, std::move(ball),
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -0.2f, 0.0f)), glm::vec3(r)),
      kPoolSphereName);
  return model;
}

}  // namespace ocean_scene
