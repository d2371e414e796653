#include "postfx_object_caustics_util.h"

#include <cmath>

namespace postfxtest {

SceneSpec ObjectHost::defaultSpec() {
  SceneSpec spec;
  spec.width = 160;
  spec.height = 96;
  spec.depthConvention = 0;
  spec.camera = {0.0, 4.0, 5.0};
  spec.lookDirection = {0.0, -0.75, -1.0};
  spec.floorY = 0.0;
  spec.sphere = false;
  return spec;
}

ObjectHost::ObjectHost(const glm::dvec3& sun, double receiverHalf, const SceneSpec& spec)
    : towardSun(glm::normalize(sun)),
      scene(spec),
      receivers(towardSun, glm::dvec3(0.0), receiverHalf, 0.0, 1024) {
  water = makeWaterTexture(16, 1, 0.0);
}

ObjectHost::~ObjectHost() {
  glDeleteTextures(1, &water);
}

postfx::FrameDesc ObjectHost::frame(const postfx::CasterMesh* casters, int count,
                                    const postfx::ObjectCausticsSettings& settings) const {
  postfx::FrameDesc f = makeFrame(scene, water, 1, glm::dvec3(0.0), -50.0);
  f.sun.direction = towardSun;
  f.objectCaustics.casters = casters;
  f.objectCaustics.casterCount = count;
  f.objectCaustics.receivers = receivers.desc();
  f.objectCaustics.settings = settings;
  return f;
}

int objectPassIndex(const postfx::FrameStats& stats) {
  for (int i = 0; i < stats.passCount; ++i)
    if (std::string(stats.passes[i].name) == "object_caustics") return i;
  return -1;
}

std::vector<glm::dvec3> readObjectMap(const postfx::ObjectCausticMap& map) {
  const std::vector<glm::vec4> rgba = readRgba(map.texture, map.size, map.size);
  std::vector<glm::dvec3> out(rgba.size());
  for (size_t i = 0; i < rgba.size(); ++i) out[i] = glm::dvec3(glm::vec3(rgba[i]));
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

bool allFinite(const std::vector<glm::dvec3>& values) {
  for (const glm::dvec3& v : values)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

}  // namespace postfxtest
