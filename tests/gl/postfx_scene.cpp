#include "postfx_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gbuffer/codec.h>
#include <glm/gtc/matrix_transform.hpp>

namespace postfxtest {
namespace {

glm::dmat4 projectionFor(const SceneSpec& s) {
  const double fov = glm::radians(s.fovYDegrees);
  const double aspect = static_cast<double>(s.width) / s.height;
  const double n = s.nearPlane, f = s.farPlane;
  if (s.depthConvention == 1) return glm::perspectiveRH_ZO(fov, aspect, n, f);
  if (s.depthConvention == 2) return glm::perspectiveRH_NO(fov, aspect, n, f);
  glm::dmat4 p(0.0);  // reverse-Z: near -> 1, far -> 0
  const double t = 1.0 / std::tan(fov * 0.5);
  p[0][0] = t / aspect;
  p[1][1] = t;
  p[2][2] = n / (f - n);
  p[2][3] = -1.0;
  p[3][2] = f * n / (f - n);
  return p;
}

double windowDepth(double viewZ, const glm::dmat4& p, int convention) {
  const double ndc = (p[2][2] * viewZ + p[3][2]) / -viewZ;
  return convention == 2 ? ndc * 0.5 + 0.5 : ndc;
}

GLuint makeTexture(GLenum format, int w, int h) {
  GLuint t = 0;
  glCreateTextures(GL_TEXTURE_2D, 1, &t);
  glTextureStorage2D(t, 1, format, w, h);
  return t;
}

}  // namespace

Scene::Scene(const SceneSpec& spec, GLenum targetFormatIn) : spec_(spec) {
  const int w = spec.width, h = spec.height;
  projection = projectionFor(spec);
  view = glm::mat4(
      glm::lookAt(glm::dvec3(0.0), glm::normalize(spec.lookDirection), glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dmat3 viewToWorld = glm::transpose(glm::dmat3(view));
  truth_.assign(static_cast<size_t>(w * h), PixelTruth{});
  std::vector<float> depthTexels(static_cast<size_t>(w * h));
  std::vector<glm::vec4> normalTexels(static_cast<size_t>(w * h));
  std::vector<glm::vec4> albedoTexels(static_cast<size_t>(w * h), glm::vec4(spec.albedo, 1.0f));
  const double farDepth = spec.depthConvention == 0 ? 0.0 : 1.0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y * w + x);
      const double ndcX = (x + 0.5) / w * 2.0 - 1.0, ndcY = (y + 0.5) / h * 2.0 - 1.0;
      // Ray at 1 m along the view axis, so the hit parameter is the view distance.
      const glm::dvec3 dirView(ndcX / projection[0][0], ndcY / projection[1][1], -1.0);
      const glm::dvec3 dir = viewToWorld * dirView;
      const glm::dvec3 eye = spec.camera - spec.camera;  // camera-relative origin
      double best = std::numeric_limits<double>::infinity();
      PixelTruth t;
      if (!spec.allSky) {
        for (double floorY : {spec.floorY, spec.floorY2}) {
          const double rel = floorY - spec.camera.y;
          if (dir.y < 0.0) {
            const double s = rel / dir.y;
            const glm::dvec3 p = eye + dir * s;
            const bool side = (p.x > spec.stepX) == (floorY == spec.floorY2);
            if (s > 0.0 && s < best && side) {
              best = s;
              t = {Hit::Floor, p, {0.0, 1.0, 0.0}};
            }
          }
        }
        if (spec.sphere) {
          const glm::dvec3 oc = eye - spec.sphereCenter;
          const double a = glm::dot(dir, dir), b = glm::dot(oc, dir);
          const double c = glm::dot(oc, oc) - spec.sphereRadius * spec.sphereRadius;
          const double disc = b * b - a * c;
          if (disc > 0.0) {
            const double s = (-b - std::sqrt(disc)) / a;
            if (s > 0.0 && s < best) {
              best = s;
              const glm::dvec3 p = eye + dir * s;
              t = {Hit::Sphere, p, glm::normalize(p - spec.sphereCenter)};
            }
          }
        }
      }
      if (best < spec.farPlane * 0.999) {
        truth_[i] = t;
        depthTexels[i] = static_cast<float>(windowDepth(-best, projection, spec.depthConvention));
        const glm::vec3 n = spec.zeroNormals ? glm::vec3(0.0f) : glm::vec3(t.normal);
        normalTexels[i] = gbuffer::shared::encodeNormal(n, spec.normalEncoding);
      } else {
        depthTexels[i] = static_cast<float>(farDepth);
        normalTexels[i] = gbuffer::shared::encodeNormal(glm::vec3(0, 1, 0), spec.normalEncoding);
      }
    }
  }
  depth = makeTexture(depthFormat, w, h);
  glTextureSubImage2D(depth, 0, 0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, depthTexels.data());
  normalFormat =
      spec.normalEncoding == 0 ? GL_RG16_SNORM : (spec.normalEncoding == 1 ? GL_RGBA16F : GL_RGBA8);
  normal = makeTexture(normalFormat, w, h);
  glTextureSubImage2D(normal, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, normalTexels.data());
  albedo = makeTexture(GL_SRGB8_ALPHA8, w, h);
  glTextureSubImage2D(albedo, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, albedoTexels.data());
  targetFormat = targetFormatIn;
  target = makeTexture(targetFormat, w, h);
  clearTarget(glm::vec4(0.0f));
}

Scene::~Scene() {
  const GLuint textures[] = {depth, normal, albedo, target};
  glDeleteTextures(4, textures);
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
  glTextureStorage3D(t, levels, GL_RGBA32F, size, size, 1);
  glTextureSubImage3D(t, 0, 0, 0, 0, size, size, 1, GL_RGBA, GL_FLOAT, texels.data());
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

}  // namespace postfxtest
