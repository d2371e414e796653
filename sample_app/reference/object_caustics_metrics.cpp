#include "object_caustics_metrics.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace ocean::reference {
namespace {

// Overlaps of the texel intervals [first + k t, first + (k + 1) t), k < texels, with the bin
// intervals [i b, (i + 1) b), i < binCount: (texel, bin, length) triples.
struct Overlap {
  int texel, bin;
  double length;
};
std::vector<Overlap> overlaps(double first, double t, int texels, double b, int binCount) {
  std::vector<Overlap> out;
  for (int k = 0; k < texels; ++k) {
    const double lo = first + k * t, hi = lo + t;
    const int i0 = std::max(0, int(std::floor(lo / b))),
              i1 = std::min(binCount - 1, int(std::floor(hi / b)));
    for (int i = i0; i <= i1; ++i) {
      const double length = std::min(hi, (i + 1) * b) - std::max(lo, i * b);
      if (length > 0.0) out.push_back({k, i, length});
    }
  }
  return out;
}

}  // namespace

std::vector<glm::dvec3> readObjectMap(const postfx::ObjectCausticMap& map) {
  const size_t texels = size_t(map.size) * size_t(map.size);
  std::vector<glm::vec4> rgba(texels);
  glGetTextureImage(map.texture, 0, GL_RGBA, GL_FLOAT, GLsizei(texels * sizeof(glm::vec4)),
                    rgba.data());
  std::vector<glm::dvec3> out(texels);
  for (size_t i = 0; i < texels; ++i) out[i] = glm::dvec3(glm::vec3(rgba[i]));
  return out;
}

glm::dvec3 mapFlux(const std::vector<glm::dvec3>& map, const postfx::ObjectCausticMap& p) {
  const double texelArea = glm::length(p.axisU) * glm::length(p.axisV) / (double(p.size) * p.size);
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& v : map) sum += v;
  return sum * texelArea;
}

glm::dvec2 focusTexel(const std::vector<glm::dvec3>& map, int size, int radius) {
  size_t best = 0;
  for (size_t i = 0; i < map.size(); ++i)
    if (map[i].g > map[best].g) best = i;
  const int bx = static_cast<int>(best % size), by = static_cast<int>(best / size);
  const double peak = map[best].g;
  glm::dvec2 sum(0.0);
  double weight = 0.0;
  for (int y = std::max(0, by - radius); y <= std::min(size - 1, by + radius); ++y)
    for (int x = std::max(0, bx - radius); x <= std::min(size - 1, bx + radius); ++x) {
      const double v = map[y * size + x].g;
      if (v < 0.5 * peak) continue;
      sum += glm::dvec2(x + 0.5, y + 0.5) * v;
      weight += v;
    }
  return sum / weight;
}

glm::dvec3 texelOnPlane(const postfx::ObjectCausticMap& map, const glm::dvec2& texel,
                        double planeY) {
  const glm::dvec3 p =
      map.origin + map.axisU * (texel.x / map.size) + map.axisV * (texel.y / map.size);
  const double t = (planeY - p.y) / map.direction.y;
  return p + map.direction * t;
}

postfx::ObjectCausticMap binGrid(const postfx::ObjectCausticMap& like, const glm::dvec3& centre,
                                 double side, int count) {
  postfx::ObjectCausticMap bins;
  bins.size = count;
  bins.direction = like.direction;
  bins.axisU = glm::normalize(like.axisU) * side;
  bins.axisV = glm::normalize(like.axisV) * side;
  bins.origin = centre - 0.5 * (bins.axisU + bins.axisV);
  return bins;
}

std::vector<double> resampleToBins(const std::vector<glm::dvec3>& map,
                                   const postfx::ObjectCausticMap& placement,
                                   const postfx::ObjectCausticMap& bins, int channel) {
  const glm::dvec3 u = glm::normalize(bins.axisU), v = glm::normalize(bins.axisV);
  const double b = glm::length(bins.axisU) / bins.size;
  const double t = glm::length(placement.axisU) / placement.size;
  // Light-plane coordinates of the map's corner relative to the bins' (the offset along the
  // light drops out of the dot products: both axes are perpendicular to it).
  const glm::dvec3 offset = placement.origin - bins.origin;
  const std::vector<Overlap> along = overlaps(glm::dot(offset, u), t, placement.size, b, bins.size);
  const std::vector<Overlap> across =
      overlaps(glm::dot(offset, v), t, placement.size, b, bins.size);
  std::vector<double> out(size_t(bins.size) * size_t(bins.size), 0.0);
  for (const Overlap& y : across)
    for (const Overlap& x : along)
      out[size_t(y.bin) * bins.size + x.bin] +=
          map[size_t(y.texel) * placement.size + x.texel][channel] * x.length * y.length;
  for (double& value : out) value /= b * b;
  return out;
}

}  // namespace ocean::reference
