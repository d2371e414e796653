#include "scene/harbour_scene.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "scene/boat_hull.h"
#include "scene/mesh_builders.h"

namespace ocean_scene {
namespace {

void appendMesh(Mesh& dst, const Mesh& src) {
  const auto base = std::uint32_t(dst.positions.size());
  dst.positions.insert(dst.positions.end(), src.positions.begin(), src.positions.end());
  dst.normals.insert(dst.normals.end(), src.normals.begin(), src.normals.end());
  for (std::uint32_t index : src.indices) dst.indices.push_back(base + index);
}

// An axis-aligned box between two corners, appended; cut in two at the level when it crosses it
// (the two halves' faces at y = 0 lie inside the box).
void addBox(Mesh& dst, glm::vec3 lo, glm::vec3 hi) {
  if (lo.y < 0.0f && hi.y > 0.0f) {
    addBox(dst, lo, {hi.x, 0.0f, hi.z});
    addBox(dst, {lo.x, 0.0f, lo.z}, hi);
    return;
  }
  Mesh box = makeBox(0.5f * (hi - lo), "");
  transformMesh(box, glm::translate(glm::mat4(1.0f), 0.5f * (lo + hi)));
  appendMesh(dst, box);
}

// A round pile standing at (x, z) from y0 to y1, appended; cut at the level like addBox.
void addPile(Mesh& dst, float x, float z, float radius, float y0, float y1) {
  if (y0 < 0.0f && y1 > 0.0f) {
    addPile(dst, x, z, radius, y0, 0.0f);
    addPile(dst, x, z, radius, 0.0f, y1);
    return;
  }
  Mesh pile = makeCylinder(radius, y0, y1, 20, "");
  transformMesh(pile, glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, z)));
  appendMesh(dst, pile);
}

Material matte(const char* name, glm::vec3 albedo, float pitch = 0.0f, float joint = 0.0f) {
  Material m;
  m.name = name;
  m.baseColor = albedo;
  m.metallic = 0.0f;
  m.roughness = 0.85f;
  m.tilePitch = pitch;
  m.tileJoint = joint;
  return m;
}

enum HarbourMaterial : std::uint32_t { kStone, kWood, kWhitePaint, kAntifouling, kVarnish };

}  // namespace

Model buildHarbourScene(const HarbourSceneParams& in) {
  HarbourSceneParams p = in;
  p.quayHeight = std::clamp(p.quayHeight, 0.1, 5.0);
  p.quayHalfLength = std::clamp(p.quayHalfLength, 5.0, 100.0);
  p.quayDepth = std::clamp(p.quayDepth, 5.0, 100.0);
  p.pierWidth = std::clamp(p.pierWidth, 1.0, 30.0);
  p.pierLength = std::clamp(p.pierLength, 1.0, 30.0);
  p.deckHeight = std::clamp(p.deckHeight, std::min(0.3, p.quayHeight), p.quayHeight);
  p.deckThickness = std::clamp(p.deckThickness, 0.05, std::min(0.5, 0.5 * p.deckHeight));
  p.pileRadius = std::clamp(p.pileRadius, 0.05, std::min(0.5, 0.2 * p.pierWidth));
  p.pileSpacing = std::clamp(p.pileSpacing, 1.0, 10.0);
  p.boatLength = std::clamp(p.boatLength, 2.0, 20.0);
  p.boatBeam = std::clamp(p.boatBeam, 1.0, 6.0);
  p.boatDraft = std::clamp(p.boatDraft, 0.1, 2.0);
  p.boatFreeboard = std::clamp(p.boatFreeboard, 0.2, 2.0);
  p.boatGap = std::clamp(p.boatGap, 0.1, 5.0);
  p.boatStern = std::clamp(p.boatStern, 0.5 * p.pierWidth + 0.5,
                           std::max(0.5 * p.pierWidth + 0.5, p.quayHalfLength - p.boatLength));

  Model model;
  // Linear albedos, light as the receivers of a harbour are: limestone ashlar in 0.6 m courses,
  // silvered oak, a white hull with dark red antifouling below the waterline and a varnished
  // strake below the gunwale.
  model.materials = {matte("harbour_stone", {0.60f, 0.57f, 0.51f}, 0.6f, 0.01f),
                     matte("harbour_wood", {0.52f, 0.48f, 0.42f}),
                     matte("harbour_white_paint", {0.78f, 0.78f, 0.74f}),
                     matte("harbour_antifouling", {0.32f, 0.08f, 0.06f}),
                     matte("harbour_varnish", {0.30f, 0.16f, 0.07f})};
  const glm::mat4 place =
      glm::translate(glm::mat4(1.0f), glm::vec3(float(p.origin.x), 0.0f, float(p.origin.y)));
  auto add = [&](Mesh mesh, HarbourMaterial material, const char* name,
                 const glm::mat4& local = glm::mat4(1.0f)) {
    mesh.name = name;
    mesh.material = material;
    addMeshInstance(model, std::move(mesh), place * local, name);
  };
  const float footing = float(kHarbourFootingY);

  // The quay: one block from below the sand to its top, its face the plane z = 0.
  Mesh quay;
  const float quayTop = float(p.quayHeight), halfLength = float(p.quayHalfLength);
  addBox(quay, {-halfLength, footing, -float(p.quayDepth)}, {halfLength, quayTop, 0.0f});
  add(std::move(quay), kStone, kHarbourQuayName);

  // The pier: its deck against the quay's face, cross beams under it at each row of piles, the
  // last row just inside its end.
  const float halfWidth = float(0.5 * p.pierWidth), length = float(p.pierLength);
  const float deckTop = float(p.deckHeight), underside = deckTop - float(p.deckThickness);
  Mesh deck;
  addBox(deck, {-halfWidth, underside, 0.0f}, {halfWidth, deckTop, length});
  add(std::move(deck), kWood, kHarbourDeckName);
  constexpr float kBeamDepth = 0.2f, kBeamHalfWidth = 0.12f, kPileInset = 0.35f;
  Mesh beams, piles;
  const float radius = float(p.pileRadius);
  for (float z = length - 0.3f; z > 0.5f; z -= float(p.pileSpacing)) {
    addBox(beams, {-halfWidth, underside - kBeamDepth, z - kBeamHalfWidth},
           {halfWidth, underside, z + kBeamHalfWidth});
    for (float x : {-halfWidth + kPileInset, halfWidth - kPileInset})
      addPile(piles, x, z, radius, footing, underside - kBeamDepth);
  }
  add(std::move(beams), kWood, kHarbourBeamsName);
  add(std::move(piles), kWood, kHarbourPilesName);

  // The boat alongside the quay, bow toward +x, its starboard side facing the harbour.
  BoatHullShape shape;
  shape.length = p.boatLength;
  shape.beam = p.boatBeam;
  shape.draft = p.boatDraft;
  shape.freeboard = p.boatFreeboard;
  BoatHull hull = buildBoatHull(shape);
  const glm::mat4 boat = glm::translate(
      glm::mat4(1.0f), glm::vec3(float(p.boatStern), 0.0f, float(p.boatGap + 0.5 * p.boatBeam)));
  add(std::move(hull.topsides), kWhitePaint, kHarbourHullName, boat);
  add(std::move(hull.bottom), kAntifouling, kHarbourBottomName, boat);
  add(std::move(hull.strake), kVarnish, kHarbourStrakeName, boat);
  add(std::move(hull.deck), kWood, kHarbourBoatDeckName, boat);
  // A small cabin a little ahead of amidships, sunk into the deck.
  const double cabinStart = 0.28 * p.boatLength, cabinEnd = 0.55 * p.boatLength;
  const float cabinHalfWidth = float(0.6 * boatHalfBeam(shape, cabinStart));
  const float cabinBottom = float(boatDeckHeight(shape, 0.0)) - 0.05f;
  const float cabinTop = float(boatDeckHeight(shape, cabinEnd)) + 0.8f;
  Mesh cabin;
  addBox(cabin, {float(cabinStart), cabinBottom, -cabinHalfWidth},
         {float(cabinEnd), cabinTop, cabinHalfWidth});
  add(std::move(cabin), kWhitePaint, kHarbourCabinName, boat);
  return model;
}

}  // namespace ocean_scene
