#pragma once
// The harbour preset's structures, added to the sea's scene: a stone quay (its wall rises from
// the sand to the quay's top), a wooden pier on round piles running out from it, and a small
// boat moored along the wall. What the waves' reflected light lands on above the water: the
// wall and the boat's side facing the harbour and the pier's underside, which nothing but that
// light reaches.
//
// Harbour-local frame (metres, y up, the water level y = 0): the quay's face is the plane z = 0
// looking toward +z, the pier's centreline is x = 0 from the face out to +z. The model is placed
// at `origin` in the world by a translation, so every height is the world's.
//
// Every mesh that crosses the level is split there (no triangle has vertices on both sides of
// y = 0): the sample's sun shadow map moves points above the level along the sun in air and
// leaves those below as they are (renderer.h, RenderSettings::airShadows), which is exact only
// for triangles on one side.
#include <glm/glm.hpp>

#include "scene/model.h"

namespace ocean_scene {

struct HarbourSceneParams {
  // World x, z of the harbour-local origin: the foot of the pier at the quay's face. Away from
  // the sea scene's landmarks near the world's origin and its sandbank, and more than the
  // shadow map's 40 m from their presets' cameras.
  glm::dvec2 origin{60.0, -60.0};
  // The quay: its top above the level (m), [0.1, 5]; its face's half-length along x and how far
  // the paved land behind it reaches (m), each in [5, 100].
  double quayHeight = 2.4;
  double quayHalfLength = 30.0;
  double quayDepth = 20.0;
  // The pier: width along x, length out from the face along z (m), each in [1, 30]; its deck's
  // top `deckHeight` above the level (m, [0.3, quayHeight], a landing stage below the quay's top
  // as harbours have them), `deckThickness` (m, [0.05, 0.5]) thick, on rows of two round piles
  // of `pileRadius` (m, [0.05, 0.5]) every `pileSpacing` (m, [1, 10]) under cross beams.
  double pierWidth = 3.0;
  double pierLength = 9.0;
  double deckHeight = 1.45;
  double deckThickness = 0.18;
  double pileRadius = 0.16;
  double pileSpacing = 2.4;
  // The boat: length and beam (m), its hull's draft below and freeboard above the level amidships
  // (m); moored with its side `boatGap` (m) off the quay's face, its stern `boatStern` (m) along
  // x from the pier's centreline, bow toward +x. Clamped to [2, 20], [1, 6], [0.1, 2], [0.2, 2],
  // [0.1, 5] and [pierWidth / 2 + 0.5, quayHalfLength - length].
  double boatLength = 6.5;
  double boatBeam = 2.3;
  double boatDraft = 0.55;
  double boatFreeboard = 0.75;
  double boatGap = 0.6;
  double boatStern = 2.9;
};

// Instance names, for tests and tools that look a part up.
inline constexpr const char* kHarbourQuayName = "harbour_quay";
inline constexpr const char* kHarbourDeckName = "harbour_pier_deck";
inline constexpr const char* kHarbourBeamsName = "harbour_pier_beams";
inline constexpr const char* kHarbourPilesName = "harbour_pier_piles";
inline constexpr const char* kHarbourHullName = "harbour_boat_hull";
inline constexpr const char* kHarbourBottomName = "harbour_boat_bottom";
inline constexpr const char* kHarbourStrakeName = "harbour_boat_strake";
inline constexpr const char* kHarbourBoatDeckName = "harbour_boat_deck";
inline constexpr const char* kHarbourCabinName = "harbour_boat_cabin";

// The pile and wall footings reach this far below the level (m): under the deepest sand
// anywhere (seabed.h's kSeabedMinHeight), so nothing stands on the seabed's exact shape.
inline constexpr double kHarbourFootingY = -14.0;

// Deterministic. Params outside their ranges are clamped into them. Materials are matte and
// opaque (none is a caustic caster): weathered wood, light limestone, white and antifouling
// paint, varnish.
Model buildHarbourScene(const HarbourSceneParams& params = {});

}  // namespace ocean_scene
