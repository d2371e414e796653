#include "photon_launch_plan.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ocean::reference {

double PhotonLaunchPlan::photons() const {
  double total = 0.0;
  for (double n : need) {
    const double side = std::ceil(std::sqrt(n));
    total += n >= 1.0 ? side * side : n;
  }
  return total;
}

PhotonLaunchPlan planPhotonLaunch(const std::vector<LaunchNeed>& needs, double cellSize,
                                  size_t maxCells) {
  PhotonLaunchPlan plan;
  glm::dvec2 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const LaunchNeed& need : needs) {
    lo = glm::min(lo, need.entry - need.reach);
    hi = glm::max(hi, need.entry + need.reach);
  }
  if (needs.empty() || !(hi.x >= lo.x) || !(hi.y >= lo.y)) return plan;
  double size = cellSize;
  for (;;) {
    const double columns = std::ceil((hi.x - lo.x) / size) + 1.0;
    const double rows = std::ceil((hi.y - lo.y) / size) + 1.0;
    if (columns * rows <= static_cast<double>(maxCells)) break;
    size *= 2.0;
  }
  plan.cellSize = size;
  // Cells aligned to multiples of the cell size in world space.
  plan.origin = glm::floor(lo / size) * size;
  plan.columns = static_cast<int>(std::ceil((hi.x - plan.origin.x) / size)) + 1;
  plan.rows = static_cast<int>(std::ceil((hi.y - plan.origin.y) / size)) + 1;
  std::vector<double> density(static_cast<size_t>(plan.columns) * plan.rows, 0.0);
  for (const LaunchNeed& need : needs) {
    // Every cell that meets the reach disc (its nearest point within reach).
    const int i0 = std::max(
        0, static_cast<int>(std::floor((need.entry.x - need.reach - plan.origin.x) / size)));
    const int i1 =
        std::min(plan.columns - 1,
                 static_cast<int>(std::floor((need.entry.x + need.reach - plan.origin.x) / size)));
    const int j0 = std::max(
        0, static_cast<int>(std::floor((need.entry.y - need.reach - plan.origin.y) / size)));
    const int j1 =
        std::min(plan.rows - 1,
                 static_cast<int>(std::floor((need.entry.y + need.reach - plan.origin.y) / size)));
    for (int j = j0; j <= j1; ++j) {
      const double z0 = plan.origin.y + j * size;
      const double dz = std::max({z0 - need.entry.y, need.entry.y - (z0 + size), 0.0});
      for (int i = i0; i <= i1; ++i) {
        const double x0 = plan.origin.x + i * size;
        const double dx = std::max({x0 - need.entry.x, need.entry.x - (x0 + size), 0.0});
        if (dx * dx + dz * dz > need.reach * need.reach) continue;
        double& d = density[static_cast<size_t>(j) * plan.columns + i];
        d = std::max(d, need.density);
      }
    }
  }
  plan.need.resize(density.size());
  for (size_t c = 0; c < density.size(); ++c) plan.need[c] = density[c] * size * size;
  return plan;
}

}  // namespace ocean::reference
