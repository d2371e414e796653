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
  // Per cell, row-major: the photons it needs per batch (max density * cell area; 0 = none).
  // A cell needing n >= 1 launches ceil(sqrt(n))^2 stratified photons; one needing n < 1
  // launches a single photon with probability n, of weight 1 / n (unbiased, and the far field
  // is not oversampled a thousandfold).
  std::vector<double> need;
  // Expected photons per batch.
  double photons() const;
};

// Cells of `cellSize` (grown when the plan would exceed maxCells) covering every need's reach
// disc, each needing the largest density among the discs that cover it.
PhotonLaunchPlan planPhotonLaunch(const std::vector<LaunchNeed>& needs, double cellSize,
                                  size_t maxCells = size_t(1) << 24);

}  // namespace ocean::reference
