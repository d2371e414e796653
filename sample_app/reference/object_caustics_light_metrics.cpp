#include "object_caustics_light_metrics.h"

#include <cmath>

namespace ocean::reference {

LightMapOnPlane lightMapOnBins(const std::vector<glm::dvec3>& map, int size,
                               const glm::dmat4& worldToMapClip, const glm::dvec3& light,
                               const ReceiverBins& bins, int subsamples) {
  const glm::dmat4 clipInverse = glm::inverse(worldToMapClip);
  // The unit direction from the light through map coordinates (texels, continuous): any two
  // points of that ray in clip space give it, whatever the map's depth convention.
  auto direction = [&](double x, double y) {
    const glm::dvec2 ndc = glm::dvec2(x, y) / double(size) * 2.0 - 1.0;
    const glm::dvec4 a = clipInverse * glm::dvec4(ndc, 0.25, 1.0);
    const glm::dvec4 b = clipInverse * glm::dvec4(ndc, 0.75, 1.0);
    glm::dvec3 d = glm::dvec3(b) / b.w - glm::dvec3(a) / a.w;
    // Along the view, away from the light.
    if (glm::dot(d, glm::dvec3(a) / a.w - light) < 0.0) d = -d;
    return glm::normalize(d);
  };
  const glm::dvec3 normal = glm::normalize(glm::cross(bins.axisU, bins.axisV));
  const double u2 = glm::dot(bins.axisU, bins.axisU), v2 = glm::dot(bins.axisV, bins.axisV);
  const double area = binArea(bins);
  LightMapOnPlane out;
  out.irradiance.assign(size_t(bins.size) * bins.size, glm::dvec3(0.0));
  const double step = 1.0 / subsamples;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3 e = map[size_t(y) * size + x];
      if (e == glm::dvec3(0.0)) continue;
      for (int j = 0; j < subsamples; ++j)
        for (int i = 0; i < subsamples; ++i) {
          const double sx = x + i * step, sy = y + j * step;
          const glm::dvec3 d00 = direction(sx, sy);
          const double solidAngle = glm::length(
              glm::cross(direction(sx + step, sy) - d00, direction(sx, sy + step) - d00));
          const glm::dvec3 d = direction(sx + 0.5 * step, sy + 0.5 * step);
          const double facing = glm::dot(d, normal);
          const double along =
              std::abs(facing) > 1e-15 ? glm::dot(bins.origin - light, normal) / facing : -1.0;
          if (!(along > 0.0)) {
            out.fluxMissing += e * solidAngle;
            continue;
          }
          // E is on a surface facing the light at the landing point: flux = E r^2 dOmega.
          const glm::dvec3 flux = e * (along * along * solidAngle);
          const glm::dvec3 rel = light + d * along - bins.origin;
          const double tu = glm::dot(rel, bins.axisU) / u2 * bins.size;
          const double tv = glm::dot(rel, bins.axisV) / v2 * bins.size;
          if (tu >= 0.0 && tv >= 0.0 && tu < bins.size && tv < bins.size) {
            out.irradiance[size_t(tv) * bins.size + size_t(tu)] += flux / area;
            out.fluxInBins += flux;
          } else {
            out.fluxOutside += flux;
          }
        }
    }
  return out;
}

glm::dvec2 binCentroid(const std::vector<glm::dvec3>& irradiance, int size) {
  glm::dvec2 sum(0.0);
  double weight = 0.0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double w = irradiance[size_t(y) * size + x].g;
      sum += w * glm::dvec2(x + 0.5, y + 0.5);
      weight += w;
    }
  return weight > 0.0 ? sum / weight : glm::dvec2(0.5 * size);
}

}  // namespace ocean::reference
