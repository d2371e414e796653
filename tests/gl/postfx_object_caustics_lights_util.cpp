#include "postfx_object_caustics_lights_util.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace postfxtest {

LightMap::LightMap(const postfx::testing::LightCausticMap& map, const glm::dvec3& lightPosition)
    : size(map.size), clipInverse(glm::inverse(map.worldToMapClip)), light(lightPosition) {
  const size_t texels = size_t(size) * size_t(size);
  std::vector<glm::vec4> rgba(texels);
  if (map.texture != 0)
    glGetTextureImage(map.texture, 0, GL_RGBA, GL_FLOAT, GLsizei(texels * sizeof(glm::vec4)),
                      rgba.data());
  value.resize(texels);
  for (size_t i = 0; i < texels; ++i) value[i] = glm::dvec3(glm::vec3(rgba[i]));
}

glm::dvec3 LightMap::direction(double x, double y) const {
  const glm::dvec4 p =
      clipInverse * glm::dvec4(x / size * 2.0 - 1.0, y / size * 2.0 - 1.0, 0.5, 1.0);
  return glm::normalize(glm::dvec3(p) / p.w - light);
}

glm::dvec3 LightMap::onPlane(double x, double y, double planeY) const {
  const glm::dvec3 d = direction(x, y);
  return light + d * ((planeY - light.y) / d.y);
}

glm::dvec3 LightMap::fluxOnPlane(double planeY) const {
  glm::dvec3 sum(0.0);
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const glm::dvec3& v = value[size_t(y) * size + x];
      if (v == glm::dvec3(0.0)) continue;
      const glm::dvec3 d = direction(x + 0.5, y + 0.5);
      const double r = (planeY - light.y) / d.y;
      const glm::dvec3 du = direction(x + 1.0, y + 0.5) - direction(x, y + 0.5);
      const glm::dvec3 dv = direction(x + 0.5, y + 1.0) - direction(x + 0.5, y);
      sum += v * (r * r * glm::length(glm::cross(du, dv)));
    }
  return sum;
}

void LightMap::spotOnPlane(double planeY, glm::dvec3& centroid, double& rmsRadius) const {
  double total = 0.0;
  glm::dvec3 sum(0.0);
  std::vector<std::pair<glm::dvec3, double>> points;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const double g = value[size_t(y) * size + x].g;
      if (!(g > 0.0)) continue;
      const glm::dvec3 d = direction(x + 0.5, y + 0.5);
      const double r = (planeY - light.y) / d.y;
      const glm::dvec3 du = direction(x + 1.0, y + 0.5) - direction(x, y + 0.5);
      const glm::dvec3 dv = direction(x + 0.5, y + 1.0) - direction(x + 0.5, y);
      const double flux = g * r * r * glm::length(glm::cross(du, dv));
      const glm::dvec3 p = light + d * r;
      points.emplace_back(p, flux);
      sum += p * flux;
      total += flux;
    }
  centroid = total > 0.0 ? sum / total : glm::dvec3(0.0);
  double m2 = 0.0;
  for (const auto& [p, w] : points) m2 += w * glm::dot(p - centroid, p - centroid);
  rmsRadius = total > 0.0 ? std::sqrt(m2 / total) : 0.0;
}

double LightMap::peak(int& px, int& py) const {
  double best = -1.0;
  px = py = 0;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      if (value[size_t(y) * size + x].g > best) {
        best = value[size_t(y) * size + x].g;
        px = x;
        py = y;
      }
  return best;
}

bool LightMap::allFinite() const {
  for (const glm::dvec3& v : value)
    if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return false;
  return true;
}

ContextPtr makeLightContext(int maxLocalLights, postfx::Feature extra) {
  postfx::CreateDesc desc;
  desc.features = postfx::Feature::ObjectCaustics | extra;
  desc.depthConvention = static_cast<postfx::DepthConvention>(0);  // as makeContext
  desc.maxLocalLights = maxLocalLights;
  postfx::Context* fx = nullptr;
  EXPECT_EQ(postfx::create(desc, fx), postfx::Result::Ok) << postfx::lastError(nullptr);
  return ContextPtr(fx);
}

postfx::ObjectCausticsSettings sizedSettings(int gridSize, int mapSize) {
  postfx::ObjectCausticsSettings s;
  s.gridSize = gridSize;
  s.mapSize = mapSize;
  return s;
}

postfx::FrameDesc lightsOnlyFrame(const ObjectHost& host, const postfx::CasterMesh* casters,
                                  int casterCount, const postfx::LocalLight* lights, int lightCount,
                                  const postfx::ObjectCausticsSettings& settings) {
  postfx::FrameDesc frame = host.frame(casters, casterCount, settings);
  frame.objectCaustics.sunCaustics = false;
  frame.objectCaustics.lights = lights;
  frame.objectCaustics.lightCount = lightCount;
  return frame;
}

bool finiteTarget(const ObjectHost& host) {
  for (const glm::vec4& v :
       readRgba(host.scene.target, host.scene.spec().width, host.scene.spec().height))
    if (!std::isfinite(v.r) || !std::isfinite(v.g) || !std::isfinite(v.b)) return false;
  return true;
}

postfx::LocalLight makeLight(postfx::LocalLightType type, const glm::dvec3& position,
                             const glm::dvec3& direction, const postfx::SunShadowMap& receivers) {
  postfx::LocalLight light;
  light.type = type;
  light.position = position;
  light.direction = direction;
  light.receivers = receivers;
  light.intensity = glm::vec3(1.0f);
  light.range = 100.0;
  return light;
}

}  // namespace postfxtest
