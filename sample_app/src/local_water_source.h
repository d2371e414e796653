#pragma once
// Local water the sample animates with the frame's clock (a pool's ripples, a wake): the renderer
// brings it to each frame's time, draws its regions' surface and hands them to the plugin
// (postfx::LocalWater), and moves the scene instances it drives (a ball, a boat).
#include <glm/glm.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include <postfx/local_water.h>

namespace ocean {

// An instance of the scene (its index in ocean_scene::Model::instances) and its transform now.
struct InstanceMove {
  std::size_t instance = 0;
  glm::dmat4 transform{1.0};
};

class LocalWaterSource {
 public:
  virtual ~LocalWaterSource() = default;
  // Brings the water to `seconds` (the frame's time). Deterministic: the same sequence of times
  // gives the same water. False with a message when the GPU work fails.
  virtual bool update(double seconds, std::string& error) = 0;
  // The regions as the plugin takes them (at most postfx::kMaxLocalWater; the sample's surface
  // draws the first), valid until the next update.
  virtual const std::vector<postfx::LocalWater>& regions() const = 0;
  // False where the scene has no sea (a pool on land: the periodic surface is not drawn, only the
  // regions' water).
  virtual bool seaVisible() const = 0;
  // The instances it moved in the last update.
  virtual const std::vector<InstanceMove>& moves() const = 0;
  // A drop where a click met the water (world x, z in m); false where no region is.
  virtual bool addDrop(glm::dvec2 worldXZ) = 0;
};

}  // namespace ocean
