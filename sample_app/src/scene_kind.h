#pragma once
// Which world a preset is shown in.
#include <cstdint>

namespace ocean {

enum class SceneKind : std::uint8_t {
  Sea,   // the default scene: the open sea over the seabed, reef, rocks, arch and models
  Pool,  // a tiled pool on land with its ripple simulation and ball (scene/pool_scene.h)
  Wake,  // the sea's scene with a ball towed across the water and its simulated wake
  // The sea's scene with a quay, a pier and a moored boat standing in the water
  // (scene/harbour_scene.h): receivers of the waves' reflected light above the level.
  Harbour,
};

}  // namespace ocean
