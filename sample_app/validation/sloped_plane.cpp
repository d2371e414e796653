#include "sloped_plane.h"

#include <algorithm>
#include <cmath>

namespace ocean::validation {

SlopedPlane slopedPlane(const SlopedPlaneDesc& desc, double level) {
  SlopedPlane s;
  s.desc = desc;
  const double slope = glm::radians(desc.slopeDegrees), sign = desc.facing < 0 ? -1.0 : 1.0;
  s.normal = {sign * std::sin(slope), std::cos(slope), 0.0};
  const glm::dvec3 up(std::cos(slope), -sign * std::sin(slope), 0.0);
  s.view = planeView(desc.width, desc.height, desc.viewDistance, s.normal, up);
  s.camera = desc.centre + desc.viewDistance * s.normal;
  const double p = s.view.pixelSize(desc.height);
  s.bins.binSize = desc.binPixels * p * std::cos(slope);  // x: down the slope, foreshortened
  s.bins.binSizeZ = desc.binPixels * p;
  s.bins.countX = desc.height / desc.binPixels;
  s.bins.countZ = desc.width / desc.binPixels;
  s.bins.origin = {desc.centre.x - 0.5 * desc.height * p * std::cos(slope),
                   desc.centre.z - 0.5 * desc.width * p};
  const double centreDepth = level - desc.centre.y;
  const double rise = 0.5 * desc.height * p * std::sin(slope);  // over half the view
  s.minDepth = centreDepth - rise;
  s.maxDepth = centreDepth + rise;
  return s;
}

ocean::reference::Receiver SlopedPlane::receiver(double level, double pad) const {
  const double centreDepth = level - desc.centre.y;
  if (desc.slopeDegrees == 0.0) return ocean::reference::Receiver::flat(centreDepth);
  ocean::reference::Receiver r;
  r.minDepth = std::max(minDepth - pad, 0.0);
  r.depth = maxDepth + pad;
  // Piecewise linear in x: the march only has to bracket the clamp's two kinks.
  r.featureSize = pad;
  const double gradient = normal.x / normal.y, x0 = desc.centre.x;
  const double lo = r.minDepth, hi = r.depth;
  r.depthAt = [=](double x, double) {
    return std::clamp(centreDepth + gradient * (x - x0), lo, hi);
  };
  return r;
}

std::vector<double> SlopedPlane::binned(const std::vector<float>& raw, double scale) const {
  const int w = desc.width, h = desc.height, b = desc.binPixels;
  std::vector<double> sum(size_t(bins.countX) * size_t(bins.countZ), 0.0);
  // Row j -> bin column j / b along x, pixel column i -> bin row i / b along z.
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i)
      sum[size_t(i / b) * size_t(bins.countX) + size_t(j / b)] += double(raw[size_t(j * w + i)]);
  for (double& v : sum) v *= scale / double(b * b);
  return sum;
}

double SlopedPlane::flatWaterFlux(const glm::dvec3& towardRefractedSun) const {
  return glm::dot(normal, towardRefractedSun) / (towardRefractedSun.y * normal.y);
}

}  // namespace ocean::validation
