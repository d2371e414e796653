// The harbour's structures (scene/harbour_scene.h): what the reflected caustics need of them.
// The pier's underside faces down, whole, above the level; the piles and the quay stand from
// under the deepest sand through the level; the boat's hull crosses the waterline, its side
// facing the harbour; no triangle crosses the level (the bent sun shadow map needs it); the
// winding agrees with the normals; nothing is a caustic caster.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "scene/boat_hull.h"
#include "scene/harbour_scene.h"
#include "scene/mesh_builders.h"
#include "scene/seabed.h"

namespace ocean_scene {
namespace {

const Instance& instanceNamed(const Model& model, const std::string& name) {
  for (const Instance& instance : model.instances)
    if (instance.name == name) return instance;
  ADD_FAILURE() << "no instance " << name;
  return model.instances.front();
}

// A triangle in world space with its face normal (from the winding) and area.
struct Triangle {
  glm::dvec3 a, b, c, normal;
  double area;
};

template <typename Visit>
void forEachTriangle(const Model& model, const Instance& instance, Visit visit) {
  const Mesh& mesh = model.meshes[instance.mesh];
  const glm::dmat4 m(instance.transform);
  auto world = [&](std::uint32_t i) {
    return glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[i]), 1.0));
  };
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    Triangle tri{
        world(mesh.indices[t]), world(mesh.indices[t + 1]), world(mesh.indices[t + 2]), {}, 0.0};
    const glm::dvec3 cross = glm::cross(tri.b - tri.a, tri.c - tri.a);
    tri.area = 0.5 * glm::length(cross);
    tri.normal = tri.area > 0.0 ? cross / (2.0 * tri.area) : glm::dvec3(0.0);
    visit(tri);
  }
}

struct Bounds {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()}, hi{-lo};
};

Bounds boundsOf(const Model& model, const Instance& instance) {
  Bounds b;
  forEachTriangle(model, instance, [&](const Triangle& t) {
    for (const glm::dvec3& p : {t.a, t.b, t.c}) {
      b.lo = glm::min(b.lo, p);
      b.hi = glm::max(b.hi, p);
    }
  });
  return b;
}

TEST(SceneHarbour, SameParamsGiveIdenticalVertexData) {
  const Model a = buildHarbourScene(), b = buildHarbourScene();
  ASSERT_EQ(a.meshes.size(), b.meshes.size());
  for (std::size_t i = 0; i < a.meshes.size(); ++i) {
    ASSERT_EQ(a.meshes[i].positions.size(), b.meshes[i].positions.size());
    EXPECT_EQ(std::memcmp(a.meshes[i].positions.data(), b.meshes[i].positions.data(),
                          a.meshes[i].positions.size() * sizeof(glm::vec3)),
              0)
        << a.meshes[i].name;
    EXPECT_EQ(a.meshes[i].indices, b.meshes[i].indices) << a.meshes[i].name;
  }
}

// Valid meshes whose every triangle winds counter-clockwise around its vertices' normals (the
// G-buffer's normals and the shadow map's culling agree), opaque matte materials.
TEST(SceneHarbour, MeshesAreValidWoundByTheirNormalsAndCastNoCaustics) {
  const Model model = buildHarbourScene();
  ASSERT_EQ(model.instances.size(), 9u);
  for (const Mesh& mesh : model.meshes) {
    ASSERT_FALSE(mesh.indices.empty()) << mesh.name;
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << mesh.name;
    ASSERT_EQ(mesh.indices.size() % 3, 0u) << mesh.name;
    ASSERT_LT(mesh.material, model.materials.size()) << mesh.name;
    EXPECT_TRUE(normalsAreUnit(mesh)) << mesh.name;
    std::size_t against = 0, total = 0;
    for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const std::uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
      ASSERT_LT(std::max({i0, i1, i2}), mesh.positions.size()) << mesh.name;
      const glm::vec3 face = glm::cross(mesh.positions[i1] - mesh.positions[i0],
                                        mesh.positions[i2] - mesh.positions[i0]);
      if (glm::length(face) < 1e-9f) continue;  // the stem's sliver at the keel
      ++total;
      if (glm::dot(face, mesh.normals[i0] + mesh.normals[i1] + mesh.normals[i2]) <= 0.0f) ++against;
    }
    EXPECT_GT(total, 0u) << mesh.name;
    EXPECT_EQ(against, 0u) << mesh.name << ": " << against << " of " << total;
  }
  for (const Material& material : model.materials) {
    EXPECT_EQ(material.transmission, 0.0f) << material.name;
    EXPECT_LT(material.metallic, 0.5f) << material.name;
    EXPECT_EQ(material.alpha, 1.0f) << material.name;
    // Light receivers: every albedo channel of the stone, wood and white paint above 0.4.
    if (material.name != "harbour_antifouling" && material.name != "harbour_varnish") {
      EXPECT_GT(std::min({material.baseColor.r, material.baseColor.g, material.baseColor.b}), 0.4f)
          << material.name;
    }
  }
}

// The sun's shadow map is bent at the level (RenderSettings::airShadows), exact only for
// triangles on one side of it.
TEST(SceneHarbour, NoTriangleCrossesTheLevel) {
  const Model model = buildHarbourScene();
  for (const Instance& instance : model.instances) {
    std::size_t crossing = 0;
    forEachTriangle(model, instance, [&](const Triangle& t) {
      const double lo = std::min({t.a.y, t.b.y, t.c.y}), hi = std::max({t.a.y, t.b.y, t.c.y});
      if (lo < 0.0 && hi > 0.0) ++crossing;
    });
    EXPECT_EQ(crossing, 0u) << instance.name;
  }
}

// The showcase: the deck's underside is one downward face over the whole pier, 1 to 1.5 m
// above the level, where only the waves' reflected light reaches.
TEST(SceneHarbour, PierUndersideFacesDownAboveTheLevelOverTheWholePier) {
  const HarbourSceneParams params;
  const Model model = buildHarbourScene(params);
  const Instance& deck = instanceNamed(model, kHarbourDeckName);
  double downArea = 0.0;
  double lowest = std::numeric_limits<double>::infinity(), highest = -lowest;
  forEachTriangle(model, deck, [&](const Triangle& t) {
    if (t.normal.y < -0.999) {
      downArea += t.area;
      for (const glm::dvec3& p : {t.a, t.b, t.c}) {
        lowest = std::min(lowest, p.y);
        highest = std::max(highest, p.y);
      }
    }
  });
  EXPECT_NEAR(downArea, params.pierWidth * params.pierLength, 1e-3);
  EXPECT_DOUBLE_EQ(lowest, highest) << "the underside is not flat";
  EXPECT_GT(lowest, 1.0);
  EXPECT_LE(lowest, 1.5);
  EXPECT_NEAR(lowest, params.deckHeight - params.deckThickness, 1e-5);
  // The pier runs out from the quay's face into the harbour (+z).
  const Bounds b = boundsOf(model, deck);
  EXPECT_NEAR(b.lo.z, params.origin.y, 1e-4);
  EXPECT_NEAR(b.hi.z, params.origin.y + params.pierLength, 1e-4);
  EXPECT_NEAR(b.hi.x - b.lo.x, params.pierWidth, 1e-4);
}

// Piles and beams hold the deck up from below the deepest sand: nothing floats, nothing stands
// on the seabed's exact shape.
TEST(SceneHarbour, PilesStandFromUnderTheSandToTheBeamsUnderTheDeck) {
  const HarbourSceneParams params;
  const Model model = buildHarbourScene(params);
  const Bounds piles = boundsOf(model, instanceNamed(model, kHarbourPilesName));
  const Bounds beams = boundsOf(model, instanceNamed(model, kHarbourBeamsName));
  EXPECT_LT(piles.lo.y, kSeabedMinHeight);
  EXPECT_NEAR(piles.hi.y, beams.lo.y, 1e-5);
  EXPECT_NEAR(beams.hi.y, params.deckHeight - params.deckThickness, 1e-5);
  // Under the deck's footprint.
  EXPECT_GE(piles.lo.x, params.origin.x - 0.5 * params.pierWidth - 1e-4);
  EXPECT_LE(piles.hi.x, params.origin.x + 0.5 * params.pierWidth + 1e-4);
  EXPECT_GT(piles.lo.z, params.origin.y);
  EXPECT_LT(piles.hi.z, params.origin.y + params.pierLength);
  // Round: every side normal horizontal, every cap flat.
  const Mesh& mesh = model.meshes[instanceNamed(model, kHarbourPilesName).mesh];
  for (const glm::vec3& n : mesh.normals)
    EXPECT_TRUE(std::abs(n.y) < 1e-6f || std::abs(std::abs(n.y) - 1.0f) < 1e-6f);
}

// The quay's wall: a vertical face at the waterline looking into the harbour (+z), from under
// the sand to the quay's top, along the whole quay.
TEST(SceneHarbour, QuayWallStandsAtTheWaterlineFacingTheHarbour) {
  const HarbourSceneParams params;
  const Model model = buildHarbourScene(params);
  const Instance& quay = instanceNamed(model, kHarbourQuayName);
  double faceArea = 0.0, lowest = 0.0, highest = 0.0;
  forEachTriangle(model, quay, [&](const Triangle& t) {
    if (t.normal.z < 0.999) return;
    EXPECT_NEAR(t.a.z, params.origin.y, 1e-4);
    faceArea += t.area;
    lowest = std::min({lowest, t.a.y, t.b.y, t.c.y});
    highest = std::max({highest, t.a.y, t.b.y, t.c.y});
  });
  EXPECT_LT(lowest, kSeabedMinHeight);
  EXPECT_NEAR(highest, params.quayHeight, 1e-5);
  EXPECT_NEAR(faceArea, 2.0 * params.quayHalfLength * (params.quayHeight - kHarbourFootingY),
              1e-2 * faceArea);
}

// The boat floats: its hull crosses the waterline, the antifouling below it, the topsides
// above it; moored off the quay's face beside the pier, its starboard side (+z) to the harbour.
TEST(SceneHarbour, BoatHullCrossesTheWaterlineBesideThePier) {
  const HarbourSceneParams params;
  const Model model = buildHarbourScene(params);
  const Bounds bottom = boundsOf(model, instanceNamed(model, kHarbourBottomName));
  const Bounds topsides = boundsOf(model, instanceNamed(model, kHarbourHullName));
  const Bounds strake = boundsOf(model, instanceNamed(model, kHarbourStrakeName));
  EXPECT_NEAR(bottom.lo.y, -params.boatDraft, 1e-5);
  EXPECT_EQ(bottom.hi.y, 0.0);
  EXPECT_EQ(topsides.lo.y, 0.0);
  EXPECT_GE(topsides.hi.y, params.boatFreeboard);  // the transom, to the gunwale
  EXPECT_GE(strake.hi.y, params.boatFreeboard);
  EXPECT_NEAR(topsides.hi.x - topsides.lo.x, params.boatLength, 1e-4);
  // Widest at the gunwale, the strake's top edge.
  EXPECT_NEAR(strake.hi.z - strake.lo.z, params.boatBeam, 1e-3);
  EXPECT_NEAR(strake.lo.z, params.origin.y + params.boatGap, 1e-3);
  EXPECT_GT(topsides.lo.x, params.origin.x + 0.5 * params.pierWidth);
  // The starboard topsides face the harbour: most of their area looks along +z.
  double toHarbour = 0.0, total = 0.0;
  forEachTriangle(model, instanceNamed(model, kHarbourHullName), [&](const Triangle& t) {
    total += t.area;
    if (t.normal.z > 0.7) toHarbour += t.area;
  });
  EXPECT_GT(toHarbour, 0.3 * total);
}

TEST(SceneHarbour, BoatDeckFollowsTheSheerAndTheStemIsSharp) {
  const BoatHullShape shape;
  EXPECT_DOUBLE_EQ(boatDeckHeight(shape, 0.0), shape.freeboard);
  EXPECT_GT(boatDeckHeight(shape, shape.length), boatDeckHeight(shape, 0.5 * shape.length));
  EXPECT_DOUBLE_EQ(boatHalfBeam(shape, 0.35 * shape.length), 0.5 * shape.beam);
  EXPECT_NEAR(boatHalfBeam(shape, shape.length), 0.0, 1e-9);
  const BoatHull hull = buildBoatHull(shape);
  for (const Mesh* mesh : {&hull.bottom, &hull.topsides, &hull.strake, &hull.deck}) {
    for (const glm::vec3& p : mesh->positions) {
      EXPECT_GE(p.x, 0.0f) << mesh->name;
      EXPECT_LE(p.x, float(shape.length) + 1e-4f) << mesh->name;
      EXPECT_LE(std::abs(p.z), float(0.5 * shape.beam) + 1e-4f) << mesh->name;
    }
  }
}

// Out-of-range params are clamped: a boat longer than the quay and a deck above it still give a
// boat alongside the quay and a deck no higher than its top.
TEST(SceneHarbour, ParamsAreClamped) {
  HarbourSceneParams params;
  params.deckHeight = 9.0;
  params.boatLength = 1e6;
  params.pileRadius = -1.0;
  const Model model = buildHarbourScene(params);
  const Bounds deck = boundsOf(model, instanceNamed(model, kHarbourDeckName));
  EXPECT_LE(deck.hi.y, params.quayHeight + 1e-5);
  const Bounds hull = boundsOf(model, instanceNamed(model, kHarbourHullName));
  EXPECT_LE(hull.hi.x - hull.lo.x, 20.0 + 1e-4);
  for (const Mesh& mesh : model.meshes)
    for (const glm::vec3& p : mesh.positions) ASSERT_TRUE(std::isfinite(p.x + p.y + p.z));
}

}  // namespace
}  // namespace ocean_scene
