#pragma once
// Where on the mean water plane the frame reference launches photons, and how densely: square
// cells, each with the density the receivers its light can reach need.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace ocean::reference {

struct LaunchNeed {
  glm::dvec2 entry;  // world xz where flat water would bring the receiver's light in (m)
  double reach;      // the light may enter up to this far from `entry` (m)
  double density;    // photons per square metre of the mean plane it needs
};

struct PhotonLaunchPlan {
  glm::dvec2 origin{0.0};  // world xz of cell (0, 0)'s corner
  double cellSize = 1.0;
  int columns = 0, rows = 0;
  std::vector<int> photonsPerSide;  // per cell, row-major; 0 = no photons
  std::uint64_t photons() const;
};

// Cells of `cellSize` (grown when the plan would exceed maxCells) covering every need's reach
// disc, each with ceil(sqrt(max density * cell area)) photons per side.
PhotonLaunchPlan planPhotonLaunch(const std::vector<LaunchNeed>& needs, double cellSize,
                                  size_t maxCells = size_t(1) << 24);

}  // namespace ocean::reference
