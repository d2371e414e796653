#include "postfx_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

namespace postfxtest {
namespace {

glm::dmat4 projectionFor(const SceneSpec& s) {
  const double fov = glm::radians(s.fovYDegrees);
  const double aspect = static_cast<double>(s.width) / s.height;
  const double n = s.nearPlane, f = s.farPlane;
  if (s.depthConvention == 1) return glm::perspectiveRH_ZO(fov, aspect, n, f);
  if (s.depthConvention == 2) return glm::perspectiveRH_NO(fov, aspect, n, f);
  return reverseZPerspective(s.fovYDegrees, aspect, n, f);
}

glm::mat4 viewFor(const SceneSpec& s) {
  return glm::mat4(
      glm::lookAt(glm::dvec3(0.0), glm::normalize(s.lookDirection), glm::dvec3(0.0, 1.0, 0.0)));
}

ocean::validation::SyntheticScene syntheticScene(const SceneSpec& s, GLenum targetFormat) {
  ocean::validation::SyntheticScene scene;
  scene.width = s.width;
  scene.height = s.height;
  scene.view = glm::dmat4(viewFor(s));  // the float view the frame gives the plugin
  scene.projection = projectionFor(s);
  scene.depthConvention = s.depthConvention;
  scene.normalEncoding = s.normalEncoding;
  scene.albedoFormat = GL_SRGB8_ALPHA8;
  scene.targetFormat = targetFormat;
  scene.maxDistance = s.farPlane * 0.999;
  scene.skyAlbedo = glm::vec4(s.albedo, 1.0f);
  scene.zeroNormals = s.zeroNormals;
  scene.allSky = s.allSky;
  using Surface = ocean::validation::SyntheticSurface;
  Surface floor;  // where x <= stepX
  floor.point = {0.0, s.floorY - s.camera.y, 0.0};
  floor.keep = {-1.0, 0.0, 0.0, s.stepX};
  floor.albedo = s.albedo;
  Surface step = floor;  // where x > stepX
  step.point.y = s.floorY2 - s.camera.y;
  step.keep = {1.0, 0.0, 0.0, -s.stepX};
  scene.surfaces = {floor, step};
  if (s.sphere) {
    Surface sphere;
    sphere.kind = Surface::Kind::Sphere;
    sphere.point = s.sphereCenter;
    sphere.radius = s.sphereRadius;
    sphere.albedo = s.albedo;
    scene.surfaces.push_back(sphere);
  }
  return scene;
}

}  // namespace

Scene::Scene(const SceneSpec& spec, GLenum targetFormatIn)
    : spec_(spec), gbuffer_(syntheticScene(spec, targetFormatIn)) {
  view = viewFor(spec);
  projection = projectionFor(spec);
  depth = gbuffer_.depth();
  normal = gbuffer_.normal();
  albedo = gbuffer_.albedo();
  target = gbuffer_.target();
  normalFormat = gbuffer_.normalFormat();
  targetFormat = targetFormatIn;
  truth_.resize(size_t(spec.width) * size_t(spec.height));
  for (int y = 0; y < spec.height; ++y) {
    for (int x = 0; x < spec.width; ++x) {
      const ocean::validation::SyntheticPixel& p = gbuffer_.pixel(x, y);
      PixelTruth& t = truth_[size_t(y) * size_t(spec.width) + size_t(x)];
      if (p.surface < 0) continue;
      t = {p.surface < 2 ? Hit::Floor : Hit::Sphere, p.position, p.normal};
    }
  }
}

void Scene::clearTarget(const glm::vec4& value) const {
  glClearTexImage(target, 0, GL_RGBA, GL_FLOAT, &value[0]);
}

GLuint makeWaterTexture(int size, int layers, double amplitude, bool nan) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
  int levels = 1;
  for (int s = size; s > 1; s >>= 1) ++levels;
  glTextureStorage3D(t, levels, GL_RGBA32F, size, size, layers);
  std::vector<glm::vec4> texels(static_cast<size_t>(size * size));
  const double twoPi = 6.283185307179586;
  for (int layer = 0; layer < layers; ++layer) {
    for (int y = 0; y < size; ++y) {
      for (int x = 0; x < size; ++x) {
        // Two plane waves per layer with whole periods per tile (seamless under GL_REPEAT).
        // Slopes are per unit uv here; the plugin sums them as dh/dx: a test-only scale.
        const double u = (x + 0.5) / size, v = (y + 0.5) / size;
        const double k1x = 2 + layer, k1y = 1, k2x = -1, k2y = 3 + layer;
        const double p1 = twoPi * (k1x * u + k1y * v), p2 = twoPi * (k2x * u + k2y * v);
        const double sx = amplitude * twoPi * (k1x * std::cos(p1) + k2x * std::cos(p2));
        const double sz = amplitude * twoPi * (k1y * std::cos(p1) + k2y * std::cos(p2));
        const double hgt = amplitude * (std::sin(p1) + std::sin(p2));
        const float q = std::numeric_limits<float>::quiet_NaN();
        texels[static_cast<size_t>(y * size + x)] =
            nan ? glm::vec4(q) : glm::vec4(float(sx), float(sz), float(hgt), 1.0f);
      }
    }
    glTextureSubImage3D(t, 0, 0, 0, layer, size, size, 1, GL_RGBA, GL_FLOAT, texels.data());
  }
  glGenerateTextureMipmap(t);
  return t;
}

GLuint makeWaterTextureFromTexels(int size, const std::vector<glm::vec4>& texels) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
  int levels = 1;
  for (int s = size; s > 1; s >>= 1) ++levels;
  const int layers = std::max(1, int(texels.size() / (size_t(size) * size)));
  glTextureStorage3D(t, levels, GL_RGBA32F, size, size, layers);
  glTextureSubImage3D(t, 0, 0, 0, 0, size, size, layers, GL_RGBA, GL_FLOAT, texels.data());
  glGenerateTextureMipmap(t);
  return t;
}

GLuint makeLevelIndependentWaterTexture(int size, double slope) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D_ARRAY, 1, &t);
  int levels = 1;
  for (int s = size; s > 1; s >>= 1) ++levels;
  glTextureStorage3D(t, levels, GL_RGBA32F, size, size, 1);
  const double twoPi = 6.283185307179586;
  for (int level = 0, n = size; level < levels; ++level, n = std::max(1, n / 2)) {
    std::vector<glm::vec4> texels(static_cast<size_t>(n * n));
    for (int y = 0; y < n; ++y) {
      for (int x = 0; x < n; ++x) {
        const double u = (x + 0.5) / n, v = (y + 0.5) / n;
        texels[static_cast<size_t>(y * n + x)] =
            glm::vec4(float(slope * std::cos(twoPi * u)), float(slope * std::cos(twoPi * v)),
                      float(slope / twoPi * (std::sin(twoPi * u) + std::sin(twoPi * v))), 1.0f);
      }
    }
    glTextureSubImage3D(t, level, 0, 0, 0, n, n, 1, GL_RGBA, GL_FLOAT, texels.data());
  }
  return t;
}

postfx::FrameDesc makeFrame(const Scene& scene, GLuint water, int cascades,
                            const glm::dvec3& offset, double level) {
  postfx::FrameDesc f;
  f.depth = {scene.depth, scene.depthFormat};
  f.normal = {scene.normal, scene.normalFormat};
  f.albedo = {scene.albedo, GL_SRGB8_ALPHA8};
  f.target = {scene.target, scene.targetFormat};
  f.camera.position = scene.spec().camera + offset;
  f.camera.view = scene.view;
  f.camera.projection = scene.projection;
  f.sun.direction = glm::normalize(glm::dvec3(0.3, 1.0, 0.2));
  f.sun.irradiance = glm::vec3(2.0f);
  f.water.level = level + offset.y;
  f.water.texture = {water, GL_RGBA32F};
  f.water.cascadeCount = cascades;
  const double tiles[] = {40.0, 10.0, 2.5, 1.25};
  for (int c = 0; c < postfx::kMaxCascades; ++c) f.water.tileSize[c] = tiles[c];
  // These scenes assert the ray-deviation model's contracts (a factor in [0, 1], no light
  // without waves to deviate it, ...); postfx_tile_irradiance_test covers the default model.
  f.caustics.model = postfx::CausticsModel::RayDeviation;
  return f;
}

std::vector<float> readRed(GLuint texture, int width, int height) {
  std::vector<float> out(static_cast<size_t>(width * height));
  glGetTextureImage(texture, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(out.size() * 4), out.data());
  return out;
}

std::vector<glm::vec4> readRgba(GLuint texture, int width, int height) {
  std::vector<glm::vec4> out(static_cast<size_t>(width * height));
  glGetTextureImage(texture, 0, GL_RGBA, GL_FLOAT, static_cast<GLsizei>(out.size() * 16),
                    out.data());
  return out;
}

glm::dmat4 reverseZPerspective(double fovYDegrees, double aspect, double nearPlane,
                               double farPlane) {
  const double fov = glm::radians(fovYDegrees), n = nearPlane, f = farPlane;
  glm::dmat4 p(0.0);
  const double t = 1.0 / std::tan(fov * 0.5);
  p[0][0] = t / aspect;
  p[1][1] = t;
  p[2][2] = n / (f - n);
  p[2][3] = -1.0;
  p[3][2] = f * n / (f - n);
  return p;
}

GLuint makeCrossingWaves(int size, double tile, double amplitude) {
  std::vector<glm::vec4> texels(static_cast<std::size_t>(size) * size);
  const double waves[][4] = {{4, 1, 1.0, 0.0}, {-2, 5, 0.6, 1.3}, {7, -3, 0.35, 2.1}};
  const double twoPi = 6.283185307179586;
  for (int j = 0; j < size; ++j)
    for (int i = 0; i < size; ++i) {
      const glm::dvec2 x = (glm::dvec2(i, j) + 0.5) * (tile / size);
      glm::dvec3 h(0.0);
      for (const auto& w : waves) {
        const glm::dvec2 k = twoPi / tile * glm::dvec2(w[0], w[1]);
        const double a = amplitude * w[2], phase = glm::dot(k, x) + w[3];
        h += glm::dvec3(a * k.x * std::cos(phase), a * k.y * std::cos(phase), a * std::sin(phase));
      }
      texels[static_cast<std::size_t>(j) * size + i] = glm::vec4(glm::vec3(h), 1.0f);
    }
  return makeWaterTextureFromTexels(size, texels);
}

FlatRegion makeFlatRegion(int size) {
  FlatRegion flat;
  glCreateTextures(GL_TEXTURE_2D, 1, &flat.texture);
  glTextureStorage2D(flat.texture, 1, GL_RGBA32F, size, size);
  const std::vector<float> zeros(static_cast<size_t>(size) * size * 4, 0.0f);
  glTextureSubImage2D(flat.texture, 0, 0, 0, size, size, GL_RGBA, GL_FLOAT, zeros.data());
  flat.region.centre = {0.0, -4.0};
  flat.region.size = {4.0, 4.0};
  flat.region.texture = {flat.texture, GL_RGBA32F};
  flat.region.gridResolution = 32;
  flat.region.depthLayers = 2;
  return flat;
}

}  // namespace postfxtest
