#pragma once
// The pool preset's scene, after Evan Wallace's webgl-water: a tiled pool (floor and four
// walls, white tiles in grey grout, a blue band at the waterline) set into a paved deck above
// the water, and a ball that moves through the water (its instance is moved every frame).
// Metres, y up; the water level is y = 0 and the pool is centred on the origin.
#include <glm/glm.hpp>

#include "scene/model.h"

namespace ocean_scene {

struct PoolSceneParams {
  // Inner extent of the pool along x and z (m), each in [1, 100]: the water's rectangle.
  glm::dvec2 size{8.0, 8.0};
  // Depth of the floor below the water level (m), (0, 20].
  double depth = 2.0;
  // Height of the deck (the pool's rim) above the water level (m), (0, 2]: the walls hide
  // the water's edge and nothing outside the pool lies below the level.
  double rimHeight = 0.3;
  // Tile pitch (m), [0.05, 2], and the grout joint between tiles (m), [0, tileSize / 4]. Tiles
  // lie on the world's grid of the pitch (a side that is not a multiple of it ends in cut
  // tiles); the renderer draws the joints, filtered (Material::tilePitch), not as geometry,
  // whose sub-pixel lines would alias into dots.
  double tileSize = 0.25;
  double groutWidth = 0.012;
  // The deck reaches this far from the pool's centre (m), beyond the pool, along x and z.
  double deckHalfExtent = 40.0;
  // The ball (m), (0, the shorter side / 4].
  double sphereRadius = 0.6;
};

// The ball's instance name: its transform is translate(centre) * scale(radius) of a unit mesh.
inline constexpr const char* kPoolSphereName = "pool_sphere";

// Deterministic. Params outside their ranges are clamped into them.
Model buildPoolScene(const PoolSceneParams& params = {});

}  // namespace ocean_scene
