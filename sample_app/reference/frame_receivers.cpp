#include "frame_receivers.h"

#include <cmath>

namespace ocean::reference {

bool FrameReceivers::project(const glm::dvec3& relative, glm::dvec2& pixel) const {
  const glm::dvec3 v = worldToView * relative;
  if (!(v.z < 0.0)) return false;
  // Inverse of gbuffer's viewPositionFromDepth: ndc = P00 x / -z - P20.
  const double ndcX = projection.x * v.x / -v.z - projection.z;
  const double ndcY = projection.y * v.y / -v.z - projection.w;
  pixel = glm::dvec2((ndcX * 0.5 + 0.5) * width, (ndcY * 0.5 + 0.5) * height);
  return std::isfinite(pixel.x) && std::isfinite(pixel.y);
}

FrameReceivers makeFrameReceivers(int width, int height, const glm::dvec3& camera,
                                  const glm::dmat3& worldToView, const glm::dvec4& projection,
                                  double level, const std::vector<glm::dvec3>& viewPositions,
                                  const std::vector<glm::dvec3>& normals,
                                  const std::vector<std::uint8_t>& sky) {
  FrameReceivers r;
  r.width = width;
  r.height = height;
  r.camera = camera;
  r.worldToView = worldToView;
  r.projection = projection;
  r.level = level;
  const size_t n = r.size();
  r.position.assign(n, glm::dvec3(0.0));
  r.normal.assign(n, glm::dvec3(0.0));
  r.valid.assign(n, 0);
  r.above.assign(n, 0);
  const glm::dmat3 viewToWorld = glm::transpose(worldToView);
  for (size_t i = 0; i < n && i < viewPositions.size() && i < normals.size() && i < sky.size();
       ++i) {
    if (sky[i]) continue;
    const glm::dvec3 p = viewToWorld * viewPositions[i];
    const glm::dvec3& normal = normals[i];
    const double length = glm::length(normal);
    if (!std::isfinite(p.x + p.y + p.z) || !(std::abs(length - 1.0) < 1e-2)) continue;
    r.position[i] = p;
    r.normal[i] = normal / length;
    r.valid[i] = r.depthBelow(i) > 0.0 ? 1 : 0;
    r.above[i] = r.depthBelow(i) < 0.0 ? 1 : 0;
  }
  return r;
}

}  // namespace ocean::reference
