#pragma once
// A small motor boat's hull, lofted through cross-sections: a transom stern, round bilges
// flaring slightly above the waterline, a sheer rising toward a sharp stem. Boat frame: metres,
// x from the transom (0) to the stem (length), z across (starboard +z), y up, the waterline y = 0.
#include "scene/model.h"

namespace ocean_scene {

struct BoatHullShape {
  double length = 6.5;      // m, transom to stem
  double beam = 2.3;        // m, widest, at the gunwale
  double draft = 0.55;      // m below the waterline at the keel, amidships
  double freeboard = 0.75;  // m from the waterline to the gunwale, amidships
};

// The hull as four meshes (material 0, outward normals, counter-clockwise seen from outside),
// split at the waterline so that no triangle crosses it: below it (keel, bilges and the
// transom's lower part), above it (topsides and the transom's upper part), the sheer strake
// (the band below the gunwale, 15 % of the freeboard, for a colour of its own) and the deck
// closing the gunwales. The sides' normals are smooth, the transom's and deck's flat.
struct BoatHull {
  Mesh bottom, topsides, strake, deck;
};

// Deterministic; the shape's values must be positive and finite (the caller clamps them).
BoatHull buildBoatHull(const BoatHullShape& shape);

// The gunwale's height above the waterline (m) at `x` along the boat, for placing things on
// the deck; the deck lies at this height.
double boatDeckHeight(const BoatHullShape& shape, double x);

// The hull's half-width at the gunwale (m) at `x` along the boat; 0 at the stem.
double boatHalfBeam(const BoatHullShape& shape, double x);

}  // namespace ocean_scene
