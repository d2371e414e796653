// Procedural default scene: determinism and the geometric contracts the lighting passes rely on.
#include <cmath>
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "scene/default_scene.h"
#include "scene/hash_noise.h"
#include "scene/mesh_builders.h"
#include "scene/scene_features.h"
#include "scene/seabed.h"

namespace ocean_scene {
namespace {

// Small enough to keep the suite fast; the contracts do not depend on resolution.
DefaultSceneParams smallParams() {
  DefaultSceneParams params;
  params.seabed.resolution = 96;
  params.farRockCount = 4;
  return params;
}

const Instance* findInstance(const Model& model, const std::string& name) {
  for (const Instance& instance : model.instances) {
    if (instance.name == name) return &instance;
  }
  return nullptr;
}

glm::vec3 toWorld(const glm::mat4& m, const glm::vec3& p) {
  return glm::vec3(m * glm::vec4(p, 1));
}

// Height of a world point above the analytic sand (negative: buried).
double heightAboveSand(const glm::vec3& w) {
  return static_cast<double>(w.y) -
         seabedHeight(static_cast<double>(w.x), static_cast<double>(w.z));
}

glm::vec3 normalToWorld(const glm::mat4& m, const glm::vec3& n) {
  return glm::normalize(glm::transpose(glm::inverse(glm::mat3(m))) * n);
}

bool sameBytes(const Mesh& a, const Mesh& b) {
  return a.positions.size() == b.positions.size() && a.normals.size() == b.normals.size() &&
         a.indices == b.indices &&
         std::memcmp(a.positions.data(), b.positions.data(),
                     a.positions.size() * sizeof(glm::vec3)) == 0 &&
         std::memcmp(a.normals.data(), b.normals.data(), a.normals.size() * sizeof(glm::vec3)) == 0;
}

TEST(SceneProcedural, SameParamsGiveIdenticalVertexData) {
  const Model a = buildDefaultScene();
  const Model b = buildDefaultScene();
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  ASSERT_EQ(a.instances.size(), b.instances.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    EXPECT_TRUE(sameBytes(a.meshes[i], b.meshes[i])) << a.meshes[i].name;
  }
  for (std::size_t i = 0; i < a.instances.size(); ++i) {
    EXPECT_EQ(a.instances[i].transform, b.instances[i].transform);
  }
}

TEST(SceneProcedural, SeedChangesRocksButNotLandmarks) {
  DefaultSceneParams other = smallParams();
  other.seed = 7;
  const Model a = buildDefaultScene(smallParams());
  const Model b = buildDefaultScene(other);
  const Instance* rockA = findInstance(a, "rock_0");
  const Instance* rockB = findInstance(b, "rock_0");
  ASSERT_NE(rockA, nullptr);
  ASSERT_NE(rockB, nullptr);
  EXPECT_FALSE(sameBytes(a.meshes[rockA->mesh], b.meshes[rockB->mesh]));
  const Instance* pillarA = findInstance(a, "pillar");
  const Instance* pillarB = findInstance(b, "pillar");
  ASSERT_NE(pillarA, nullptr);
  ASSERT_NE(pillarB, nullptr);
  EXPECT_EQ(pillarA->transform, pillarB->transform);
}

TEST(SceneProcedural, DefaultSeabedResolvesRipplesNearTheCentre) {
  const SeabedMeshParams params;  // defaults
  EXPECT_EQ(params.resolution, 512);
  // Spacing at the centre and at the edge of the ripple field (four samples per ripple).
  const int mid = params.resolution / 2;
  EXPECT_NEAR(seabedGridCoordinate(mid, params) - seabedGridCoordinate(mid - 1, params),
              params.centreSpacing, 0.01);
  for (int i = mid; i + 1 < params.resolution; ++i) {
    const double x = seabedGridCoordinate(i, params);
    if (x > kRippleFieldRadius) break;
    EXPECT_LE(seabedGridCoordinate(i + 1, params) - x, kRippleWavelength / 3.0) << "x = " << x;
  }
  EXPECT_DOUBLE_EQ(seabedGridCoordinate(0, params), -params.halfExtent);
  EXPECT_DOUBLE_EQ(seabedGridCoordinate(params.resolution - 1, params), params.halfExtent);
  for (int i = 0; i + 1 < params.resolution; ++i) {
    ASSERT_LT(seabedGridCoordinate(i, params), seabedGridCoordinate(i + 1, params));
  }
}

TEST(SceneProcedural, SeabedStaysWithinItsBoundsAndBelowWater) {
  for (double z = -160.0; z <= 160.0; z += 0.37) {
    for (double x = -160.0; x <= 160.0; x += 0.37) {
      const double h = seabedHeight(x, z);
      ASSERT_LE(h, kSeabedMaxHeight) << x << ", " << z;
      ASSERT_GE(h, kSeabedMinHeight) << x << ", " << z;
    }
  }
}

TEST(SceneProcedural, SeabedGradientMatchesFiniteDifferences) {
  HashRng rng(42);
  const double eps = 1e-5;
  for (int i = 0; i < 2000; ++i) {
    // Half the samples inside the ripple field and its fade ring, where the terms are stiffest.
    const double range = i % 2 == 0 ? 40.0 : 150.0;
    const double x = rng.uniform(-range, range), z = rng.uniform(-range, range);
    const glm::dvec2 g = seabedGradient(x, z);
    const double gx = (seabedHeight(x + eps, z) - seabedHeight(x - eps, z)) / (2 * eps);
    const double gz = (seabedHeight(x, z + eps) - seabedHeight(x, z - eps)) / (2 * eps);
    ASSERT_NEAR(g.x, gx, 1e-6) << x << ", " << z;
    ASSERT_NEAR(g.y, gz, 1e-6) << x << ", " << z;
    const glm::dvec3 n = seabedNormal(x, z);
    ASSERT_NEAR(glm::length(n), 1.0, 1e-12);
    ASSERT_GT(n.y, 0.0);
  }
}

TEST(SceneProcedural, SeabedMeshSamplesTheAnalyticSurface) {
  SeabedMeshParams params;
  params.resolution = 64;
  const Mesh mesh = buildSeabedMesh(params);
  ASSERT_EQ(mesh.positions.size(), 64u * 64u);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 p = mesh.positions[i];
    ASSERT_NEAR(p.y, seabedHeight(p.x, p.z), 1e-4);
    const glm::dvec3 n = seabedNormal(p.x, p.z);
    ASSERT_NEAR(mesh.normals[i].y, n.y, 1e-5);
  }
}

TEST(SceneProcedural, AllMeshesAreValidAndBelowWater) {
  const Model scene = buildDefaultScene(smallParams());
  ASSERT_GE(scene.instances.size(), 5u + 8u);
  for (const Mesh& mesh : scene.meshes) {
    ASSERT_FALSE(mesh.positions.empty()) << mesh.name;
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << mesh.name;
    ASSERT_EQ(mesh.indices.size() % 3, 0u) << mesh.name;
    ASSERT_LT(mesh.material, scene.materials.size()) << mesh.name;
    EXPECT_TRUE(normalsAreUnit(mesh)) << mesh.name;
    for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.positions.size()) << mesh.name;
  }
  for (const Instance& instance : scene.instances) {
    const Mesh& mesh = scene.meshes[instance.mesh];
    for (const glm::vec3& p : mesh.positions) {
      const glm::vec3 w = toWorld(instance.transform, p);
      ASSERT_TRUE(std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) << mesh.name;
      ASSERT_LT(w.y, 0.0f) << mesh.name;
    }
  }
}

// Counter-clockwise winding must agree with the normals, or back-face culling and
// shadow-map biasing go wrong on exactly the surfaces the caustics need.
TEST(SceneProcedural, WindingAgreesWithNormals) {
  const Model scene = buildDefaultScene(smallParams());
  for (const Mesh& mesh : scene.meshes) {
    std::size_t agree = 0, total = 0;
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
      const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                      c = mesh.positions[mesh.indices[t + 2]];
      const glm::vec3 face = glm::cross(b - a, c - a);
      if (glm::length(face) < 1e-10f) continue;
      const glm::vec3 n = mesh.normals[mesh.indices[t]] + mesh.normals[mesh.indices[t + 1]] +
                          mesh.normals[mesh.indices[t + 2]];
      ++total;
      if (glm::dot(face, n) > 0.0f) ++agree;
    }
    ASSERT_GT(total, 0u) << mesh.name;
    // Noise-displaced rocks may fold a few triangles; everything else must agree exactly.
    EXPECT_GE(static_cast<double>(agree), 0.995 * static_cast<double>(total)) << mesh.name;
    if (mesh.name.find("rock") == std::string::npos) {
      EXPECT_EQ(agree, total) << mesh.name;
    }
  }
}

TEST(SceneProcedural, PillarSidesAreVerticalAndReachFromSandToTop) {
  const Model scene = buildDefaultScene(smallParams());
  const Instance* pillar = findInstance(scene, "pillar");
  ASSERT_NE(pillar, nullptr);
  const Mesh& mesh = scene.meshes[pillar->mesh];
  int sideVertices = 0;
  float top = -1e9f, bottom = 1e9f;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 w = toWorld(pillar->transform, mesh.positions[i]);
    const glm::vec3 n = normalToWorld(pillar->transform, mesh.normals[i]);
    top = std::max(top, w.y);
    bottom = std::min(bottom, w.y);
    if (std::abs(n.y) < 0.5f) {
      EXPECT_NEAR(n.y, 0.0f, 1e-6f);
      ++sideVertices;
    }
    const glm::vec2 d(w.x - static_cast<float>(features::kPillarXZ.x),
                      w.z - static_cast<float>(features::kPillarXZ.y));
    EXPECT_LE(glm::length(d),
              static_cast<float>(features::kPillarHalfWidth * std::sqrt(2.0)) + 1e-4f);
  }
  EXPECT_EQ(sideVertices, 16);
  EXPECT_NEAR(top, features::kPillarTopY, 1e-4);
  EXPECT_LT(bottom, seabedHeight(features::kPillarXZ.x, features::kPillarXZ.y) - 0.5);
}

TEST(SceneProcedural, ColumnAndWallHaveHorizontalSideNormals) {
  const Model scene = buildDefaultScene(smallParams());
  for (const char* name : {"column", "wall"}) {
    const Instance* instance = findInstance(scene, name);
    ASSERT_NE(instance, nullptr) << name;
    const Mesh& mesh = scene.meshes[instance->mesh];
    int sides = 0;
    for (const glm::vec3& local : mesh.normals) {
      const glm::vec3 n = normalToWorld(instance->transform, local);
      if (std::abs(n.y) < 0.5f) {
        EXPECT_NEAR(n.y, 0.0f, 1e-6f) << name;
        ++sides;
      }
    }
    EXPECT_GE(sides, 16) << name;
  }
}

TEST(SceneProcedural, ArchHasAnOverhangAboveTheSand) {
  const Model scene = buildDefaultScene(smallParams());
  const Instance* arch = findInstance(scene, "rock_arch");
  ASSERT_NE(arch, nullptr);
  const Mesh& mesh = scene.meshes[arch->mesh];
  int overhang = 0;
  float highestUnderside = -1e9f;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::vec3 w = toWorld(arch->transform, mesh.positions[i]);
    const glm::vec3 n = normalToWorld(arch->transform, mesh.normals[i]);
    if (n.y < -0.7f && heightAboveSand(w) > 2.0) {
      ++overhang;
      highestUnderside = std::max(highestUnderside, w.y);
    }
  }
  EXPECT_GT(overhang, 50);
  // The underside near the apex is several metres up: a real shadowed overhang.
  EXPECT_GT(highestUnderside,
            seabedHeight(features::kArchShadowXZ.x, features::kArchShadowXZ.y) + 3.0);
  // The feet are buried: the lowest vertex is under the sand.
  float lowestMargin = 1e9f;
  for (const glm::vec3& p : mesh.positions) {
    const glm::vec3 w = toWorld(arch->transform, p);
    lowestMargin = std::min(lowestMargin, static_cast<float>(heightAboveSand(w)));
  }
  EXPECT_LT(lowestMargin, -1.0f);
}

TEST(SceneProcedural, RocksArePartlyBuried) {
  const Model scene = buildDefaultScene(smallParams());
  int rocks = 0;
  for (const Instance& instance : scene.instances) {
    if (instance.name.rfind("rock_", 0) != 0 || instance.name == "rock_arch") continue;
    ++rocks;
    int above = 0, below = 0;
    for (const glm::vec3& p : scene.meshes[instance.mesh].positions) {
      const glm::vec3 w = toWorld(instance.transform, p);
      (heightAboveSand(w) > 0.0 ? above : below)++;
    }
    EXPECT_GT(above, 0) << instance.name;
    EXPECT_GT(below, 0) << instance.name;
  }
  EXPECT_EQ(rocks, 8);
}

TEST(SceneProcedural, IcosphereIsAUnitSphere) {
  const Mesh mesh = makeIcosphere(3, "s");
  EXPECT_EQ(mesh.positions.size(), 642u);
  EXPECT_EQ(mesh.indices.size(), 1280u * 3u);
  for (const glm::vec3& p : mesh.positions) ASSERT_NEAR(glm::length(p), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace ocean_scene
