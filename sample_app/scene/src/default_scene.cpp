#include "scene/default_scene.h"

#include <array>
#include <cmath>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/hash_noise.h"
#include "scene/mesh_builders.h"
#include "scene/scene_features.h"
#include "scene/scene_parts.h"

namespace ocean_scene {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kBaseBurial = 1.0;  // metres of pillar/wall/column below the lowest sand

// sRGB albedos of sand and stone converted to linear.
std::vector<Material> defaultMaterials() {
  Material sand;
  sand.name = "sand";
  sand.baseColor = {0.54f, 0.45f, 0.22f};
  sand.metallic = 0.0f;
  sand.roughness = 0.9f;
  Material rock;
  rock.name = "rock";
  rock.baseColor = {0.30f, 0.27f, 0.22f};  // wet limestone; the renderer adds its noise
  rock.metallic = 0.0f;
  rock.roughness = 0.85f;
  rock.proceduralRock = true;
  Material stone;
  stone.name = "stone";
  stone.baseColor = {0.36f, 0.35f, 0.32f};
  stone.metallic = 0.0f;
  stone.roughness = 0.75f;
  stone.proceduralRock = true;
  return {sand, rock, stone};
}

glm::mat4 translation(double x, double y, double z) {
  return glm::translate(glm::mat4(1.0f), glm::vec3(static_cast<float>(x), static_cast<float>(y),
                                                   static_cast<float>(z)));
}

glm::mat4 yaw(double degrees) {
  return glm::rotate(glm::mat4(1.0f), static_cast<float>(degrees * kPi / 180.0),
                     glm::vec3(0.0f, 1.0f, 0.0f));
}

struct RockSpot {
  double x, z, radius;
};

// Hand-placed so they frame the landmarks without touching them.
constexpr std::array<RockSpot, 8> kNearRocks = {
    RockSpot{3.5, 5.0, 1.2},    RockSpot{-1.5, -4.5, 0.8},  RockSpot{9.0, 7.0, 1.6},
    RockSpot{-13.0, -3.0, 2.0}, RockSpot{11.0, -11.0, 1.4}, RockSpot{-6.0, 13.0, 1.1},
    RockSpot{2.0, -13.0, 2.4},  RockSpot{-17.0, 11.0, 1.3}};

// heightScale: 1 for the low boulders of the deep scene, more for the reef's taller heads.
void addRock(Model& scene, const DefaultSceneParams& params, std::uint32_t rockSeed, double x,
             double z, double radius, const std::string& name, double heightScale = 1.0) {
  HashRng rng(rockSeed);
  RockParams rock;
  rock.radius = radius;
  rock.stretch = {rng.uniform(0.9, 1.25), heightScale * rng.uniform(0.55, 0.8),
                  rng.uniform(0.85, 1.2)};
  rock.roughness = rng.uniform(0.3, 0.45);
  rock.subdivisions = params.rockSubdivisions;
  rock.seed = rockSeed;
  Mesh mesh = buildRock(rock, name);
  mesh.material = kRockMaterial;
  // Sunk by a third of its height so it sits in the sand rather than on it.
  const double y = seabedHeight(x, z) - 0.35 * radius * rock.stretch.y;
  addMeshInstance(scene, std::move(mesh), translation(x, y, z) * yaw(rng.uniform(0.0, 360.0)),
                  name);
}

void addRocks(Model& scene, const DefaultSceneParams& params) {
  for (std::size_t i = 0; i < kNearRocks.size(); ++i) {
    const RockSpot& spot = kNearRocks[i];
    const std::uint32_t rockSeed = hashCombine(params.seed, static_cast<std::uint32_t>(i));
    addRock(scene, params, rockSeed, spot.x, spot.z, spot.radius, "rock_" + std::to_string(i));
  }
  for (std::size_t i = 0; i < std::size(features::kReefRocks); ++i) {
    const features::ReefRock& spot = features::kReefRocks[i];
    const std::uint32_t rockSeed = hashCombine(params.seed, 500U + static_cast<std::uint32_t>(i));
    addRock(scene, params, rockSeed, spot.x, spot.z, spot.radius, "reef_rock_" + std::to_string(i),
            1.6);
  }
  HashRng layout(hashCombine(params.seed, 0xfa7U));
  for (int i = 0; i < params.farRockCount; ++i) {
    const double angle = layout.uniform(0.0, 2.0 * kPi);
    const double distance = layout.uniform(40.0, 120.0);
    const double radius = layout.uniform(1.0, 4.0);
    const std::uint32_t rockSeed = hashCombine(params.seed, 1000U + static_cast<std::uint32_t>(i));
    addRock(scene, params, rockSeed, distance * std::cos(angle), distance * std::sin(angle), radius,
            "far_rock_" + std::to_string(i));
  }
}

void addPillar(Model& scene) {
  using namespace features;
  const double bottom = lowestSandUnder(kPillarXZ, kPillarHalfWidth * 1.5) - kBaseBurial;
  const double halfHeight = 0.5 * (kPillarTopY - bottom);
  Mesh mesh =
      makeBox(glm::vec3(static_cast<float>(kPillarHalfWidth), static_cast<float>(halfHeight),
                        static_cast<float>(kPillarHalfWidth)),
              "pillar");
  mesh.material = kStoneMaterial;
  addMeshInstance(scene, std::move(mesh),
                  translation(kPillarXZ.x, bottom + halfHeight, kPillarXZ.y) * yaw(kPillarYawDeg),
                  "pillar");
}

void addColumn(Model& scene) {
  using namespace features;
  const double bottom = lowestSandUnder(kColumnXZ, kColumnRadius) - kBaseBurial;
  Mesh mesh = makeCylinder(static_cast<float>(kColumnRadius), static_cast<float>(bottom),
                           static_cast<float>(kColumnTopY), 40, "column");
  mesh.material = kStoneMaterial;
  addMeshInstance(scene, std::move(mesh), translation(kColumnXZ.x, 0.0, kColumnXZ.y), "column");
}

void addWall(Model& scene) {
  using namespace features;
  const double bottom = lowestSandUnder(kWallXZ, kWallHalfExtent.z) - kBaseBurial;
  const double halfHeight = 0.5 * (kWallTopY - bottom);
  Mesh mesh =
      makeBox(glm::vec3(static_cast<float>(kWallHalfExtent.x), static_cast<float>(halfHeight),
                        static_cast<float>(kWallHalfExtent.z)),
              "wall");
  mesh.material = kStoneMaterial;
  addMeshInstance(scene, std::move(mesh), translation(kWallXZ.x, bottom + halfHeight, kWallXZ.y),
                  "wall");
}

void addArch(Model& scene, std::uint32_t seed) {
  using namespace features;
  // The centreline sits a little below the sand at the feet, so no gap shows under them.
  const double leftFoot = seabedHeight(kArchXZ.x - kArchRadius, kArchXZ.y);
  const double rightFoot = seabedHeight(kArchXZ.x + kArchRadius, kArchXZ.y);
  const double baseY = std::min(lowestSandUnder({kArchXZ.x - kArchRadius, kArchXZ.y}, 1.5),
                                lowestSandUnder({kArchXZ.x + kArchRadius, kArchXZ.y}, 1.5)) -
                       0.3;
  const double footDepth = std::max(leftFoot, rightFoot) - baseY + 1.5;
  Mesh mesh = buildArch(footDepth, seed);
  mesh.material = kRockMaterial;
  addMeshInstance(scene, std::move(mesh), translation(kArchXZ.x, baseY, kArchXZ.y), "rock_arch");
}

}  // namespace

double lowestSandUnder(const glm::dvec2& centre, double halfSize) {
  constexpr int kSamples = 9;
  double lowest = seabedHeight(centre.x, centre.y);
  for (int j = 0; j < kSamples; ++j) {
    for (int i = 0; i < kSamples; ++i) {
      const double x = centre.x + halfSize * (2.0 * i / (kSamples - 1) - 1.0);
      const double z = centre.y + halfSize * (2.0 * j / (kSamples - 1) - 1.0);
      lowest = std::min(lowest, seabedHeight(x, z));
    }
  }
  return lowest;
}

Model buildDefaultScene(const DefaultSceneParams& params) {
  Model scene;
  scene.materials = defaultMaterials();
  Mesh seabed = buildSeabedMesh(params.seabed);
  seabed.material = kSandMaterial;
  addMeshInstance(scene, std::move(seabed), glm::mat4(1.0f), "seabed");
  addPillar(scene);
  addColumn(scene);
  addWall(scene);
  addArch(scene, hashCombine(params.seed, 0xa5c4U));
  addRocks(scene, params);
  return scene;
}

}  // namespace ocean_scene
